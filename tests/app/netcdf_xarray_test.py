#!/usr/bin/python3
"""results.nc in xarray (issue 12, part 3): `xarray.open_dataset("results.nc")` opens it with no
extra arguments, and its dimensions, units and values agree with timeseries.csv and
equilibrium.csv, as those print them; z (issue 19) is 0 throughout for P63, in the x-y plane,
and for P63 turned out of its plane by a current across it (heading 90 degrees) and a sway of
its fairlead along z, z agrees with the CSV files and z_end is eq. (3)'s trochoid along z. A
system's results.nc (scenes/floating_platform.toml cut to 5 s) holds its points.csv, body.csv
and each line's timeseries.csv rows.

    /usr/bin/python3 tests/app/netcdf_xarray_test.py --cablefilm build/cablefilm \\
        --scene scenes/polachek1963.toml --out-dir /tmp/netcdf_xarray

Runs case P63 cut to 5 s without its film, then its 3D variant cut to 3 s. Exits 77 (skipped, with a message) when xarray or
its netCDF backend (python3-netcdf4 or python3-h5netcdf) is missing: scripts/setup.sh --tests
installs them. Prints one line per check and `N passed, M failed`.
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys

SKIP = 77


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--cablefilm', required=True)
    p.add_argument('--scene', required=True)
    p.add_argument('--out-dir', required=True)
    a = p.parse_args()
    try:
        import numpy as np
        import xarray as xr
    except ImportError as e:
        print(f'skipped: xarray is not installed ({e}); scripts/setup.sh --tests installs '
              'python3-xarray')
        return SKIP
    engines = set(xr.backends.list_engines())
    if not engines & {'netcdf4', 'h5netcdf'}:
        print(f'skipped: xarray has no NetCDF-4 backend (engines: {sorted(engines)}); '
              'scripts/setup.sh --tests installs python3-netcdf4')
        return SKIP

    shutil.rmtree(a.out_dir, ignore_errors=True)
    os.makedirs(a.out_dir)
    scene_text = open(a.scene).read()

    def run(name, text):
        scene = os.path.join(a.out_dir, name + '.toml')
        with open(scene, 'w') as f:
            f.write(text)
        out = os.path.join(a.out_dir, name)
        done = subprocess.run([a.cablefilm, 'run', scene, '--no-film', '--out', out],
                              capture_output=True, text=True)
        if done.returncode != 0:
            print(f'FAIL  cablefilm run {name}: exit {done.returncode}: '
                  f'{done.stderr.strip()[-500:]}')
            print('0 passed, 1 failed')
            sys.exit(1)
        return out

    text = re.sub(r'^duration = .*$', 'duration = 5.0', scene_text, flags=re.M)
    out = run('p63_short', text)
    text_3d = re.sub(r'^duration = .*$', 'duration = 3.0', scene_text, flags=re.M)
    text_3d = re.sub(r'^current = 0\.0 ', 'current = 0.5\ncurrent_heading = 90.0 ', text_3d,
                     flags=re.M)
    text_3d = re.sub(r'^(y_amplitudes = \[0\.0, 1\.8288\])', r'\1\nz_amplitudes = [0.0, 1.0]',
                     text_3d, flags=re.M)
    out_3d = run('p63_3d', text_3d)

    results = []

    def check(name, ok, detail=''):
        results.append((name, bool(ok), detail))

    with open(os.path.join(out, 'timeseries.csv')) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out, 'equilibrium.csv')) as f:
        eq = list(csv.DictReader(f))

    ds = xr.open_dataset(os.path.join(out, 'results.nc'))  # no extra arguments
    with ds:
        check('dimensions', dict(ds.sizes) == {'time': len(rows), 'station': 61, 'link': 60},
              dict(ds.sizes))
        check('time is unlimited', ds.encoding.get('unlimited_dims') == {'time'},
              ds.encoding.get('unlimited_dims'))
        check('time is seconds, as numbers', ds.time.dtype == np.float64, ds.time.dtype)
        units = {'time': 's', 'x': 'm', 'y': 'm', 'z': 'm', 'tension': 'N', 's': 'm',
                 's_link': 'm', 'x_start': 'm', 'y_start': 'm', 'z_start': 'm', 'x_end': 'm',
                 'y_end': 'm', 'z_end': 'm', 'x_equilibrium': 'm', 'y_equilibrium': 'm',
                 'z_equilibrium': 'm', 'tension_equilibrium': 'N'}
        got = {k: ds[k].attrs.get('units') for k in units}
        check('units', got == units, got)
        names = list(ds.variables)
        check('a long_name on every variable', all(ds[k].attrs.get('long_name') for k in names),
              [k for k in names if not ds[k].attrs.get('long_name')])
        check('dims of x, y, z, tension',
              (ds.x.dims, ds.y.dims, ds.z.dims, ds.tension.dims) ==
              (('time', 'station'), ('time', 'station'), ('time', 'station'), ('time', 'link')),
              (ds.x.dims, ds.y.dims, ds.z.dims, ds.tension.dims))
        check('arc lengths are coordinates', 's' in ds.x.coords and 's' in ds.z.coords and
              's_link' in ds.tension.coords, list(ds.coords))
        check('Conventions', ds.attrs.get('Conventions') == 'CF-1.8', ds.attrs.get('Conventions'))
        check('title', ds.attrs.get('title') == 'Sample mooring line, Polachek et al. 1963',
              ds.attrs.get('title'))
        check('the scene text', ds.attrs.get('scene') == text)
        check('the program version', str(ds.attrs.get('cablefilm_version', '')).startswith('0.'),
              ds.attrs.get('cablefilm_version'))
        enc = ds.x.encoding
        # A small file (under 16 MiB of rows): stored as it is, not deflated.
        check('x not deflated (a small file)', not enc.get('zlib') and not enc.get('shuffle'),
              {k: enc.get(k) for k in ('zlib', 'complevel', 'shuffle')})
        check('x chunked by time, all stations', enc.get('chunksizes', (0, 0))[1] == 61 and
              enc.get('chunksizes', (0, 0))[0] > 1, enc.get('chunksizes'))

        # Every row against timeseries.csv, as it prints its numbers.
        tension = ds.tension.values
        tmax = ds.tension.max('link').values
        link_max = ds.tension.argmax('link').values
        fmt10 = lambda v: '%.10g' % v
        fmt12 = lambda v: '%.12g' % v
        bad = []
        for r, row in enumerate(rows):
            want = (row['t'], row['x_end'], row['y_end'], row['z_end'], row['tension_start'],
                    row['tension_end'], row['tension_max'], row['link_max'])
            have = (fmt10(ds.time.values[r]), fmt12(ds.x_end.values[r]),
                    fmt12(ds.y_end.values[r]), fmt12(ds.z_end.values[r]), fmt10(tension[r, 0]),
                    fmt10(tension[r, -1]), fmt10(tmax[r]), str(int(link_max[r])))
            if want != have:
                bad.append((r, want, have))
        check('every row of timeseries.csv (t, x_end, y_end, z_end, start, end, max, link_max)',
              not bad, bad[:3])
        check('x_end, y_end, z_end are the last station',
              all(np.array_equal(ds[f'{c}_end'], ds[c][:, -1]) for c in 'xyz'))
        check('x_start, y_start, z_start are the first station',
              all(np.array_equal(ds[f'{c}_start'], ds[c][:, 0]) for c in 'xyz'))
        check('P63 is in the x-y plane: z, z_start, z_end, z_equilibrium all exactly 0',
              all(not np.any(ds[k].values) for k in ('z', 'z_start', 'z_end', 'z_equilibrium'))
              and all(row['z_end'] == '0' for row in rows))
        # One link at one time, by label, against the CSV's tension_start at t = 2 s.
        row = next(r for r in rows if r['t'] == '2')
        check('tension.sel(time=2, link=0) is tension_start at t = 2',
              fmt10(ds.tension.sel(time=2.0, link=0, method='nearest')) == row['tension_start'],
              (float(ds.tension.sel(time=2.0, link=0, method='nearest')), row['tension_start']))
        # The equilibrium against equilibrium.csv.
        bad = []
        for j, row in enumerate(eq):
            have = (fmt10(ds.s.values[j]), fmt12(ds.x_equilibrium.values[j]),
                    fmt12(ds.y_equilibrium.values[j]), fmt12(ds.z_equilibrium.values[j]),
                    fmt10(ds.tension_equilibrium.values[j]) if j < 60 else '')
            if have != (row['s'], row['x'], row['y'], row['z'], row['tension']):
                bad.append((j, row, have))
        check('equilibrium.csv (s, x, y, z, tension)', not bad, bad[:3])
        check('the first row is the equilibrium',
              all(np.array_equal(ds[c][0], ds[f'{c}_equilibrium']) for c in 'xyz'))
        check('s_link is the link midpoints',
              np.allclose(ds.s_link, 0.5 * (ds.s.values[:-1] + ds.s.values[1:]), rtol=0,
                          atol=1e-12))

    # P63 out of its plane: z as the CSV files print it, and z_end as eq. (3) along z.
    with open(os.path.join(out_3d, 'timeseries.csv')) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out_3d, 'equilibrium.csv')) as f:
        eq = list(csv.DictReader(f))
    with xr.open_dataset(os.path.join(out_3d, 'results.nc')) as ds:
        t = ds.time.values
        check('3D: z_end of every row of timeseries.csv',
              [row['z_end'] for row in rows] == [fmt12(v) for v in ds.z_end.values])
        check('3D: z of equilibrium.csv',
              [row['z'] for row in eq] == [fmt12(v) for v in ds.z_equilibrium.values])
        check('3D: z_end is the last station, z_start the first',
              np.array_equal(ds.z_end, ds.z[:, -1]) and np.array_equal(ds.z_start, ds.z[:, 0]))
        # z = R(t) (0 cos wt + 1 m sin wt), w = 2 pi / 10 s, R = 1 - (1 + 0.5 t) exp(-0.5 t):
        # the same formula in another arrangement, round-off of 1e-16 m; 1e-12 m leaves room.
        trochoid = (1 - (1 + 0.5 * t) * np.exp(-0.5 * t)) * np.sin(2 * np.pi * t / 10)
        check('3D: z_end is the trochoid along z',
              np.max(np.abs(ds.z_end.values - trochoid)) < 1e-12,
              np.max(np.abs(ds.z_end.values - trochoid)))
        check('3D: the anchor stays at z = 0', not np.any(ds.z_start.values))
        interior = ds.z.values[:, 1:-1]
        check('3D: the current along +z pushes every other station to z > 0',
              np.all(interior > 0) and interior.max() > 1.0, interior.min())
        check('3D: the end sways out of the plane', np.max(np.abs(ds.z_end.values)) > 0.4,
              np.max(np.abs(ds.z_end.values)))

    # A system's results.nc (issue 20): the points, lines and bodies of
    # scenes/floating_platform.toml cut to 5 s, against points.csv, body.csv and each line's
    # timeseries.csv, as those print them.
    platform = open(os.path.join(os.path.dirname(a.scene), 'floating_platform.toml')).read()
    out_sys = run('platform_short', re.sub(r'^duration = .*$', 'duration = 5.0', platform,
                                           flags=re.M))

    def table(*path):
        with open(os.path.join(out_sys, *path)) as f:
            return list(csv.DictReader(f))

    points = table('points.csv')
    bodies = table('body.csv')
    with xr.open_dataset(os.path.join(out_sys, 'results.nc')) as ds:
        point_names = [str(v) for v in ds.point_name.values]
        line_names = [str(v) for v in ds.line_name.values]
        rows = len(points) // len(point_names)
        check('system: dimensions', dict(ds.sizes) == {'time': rows, 'line': 3, 'point': 6,
                                                         'body': 1}, dict(ds.sizes))
        check('system: names', line_names == ['leg1', 'leg2', 'leg3'] and
              point_names == [r['point'] for r in points[:len(point_names)]] and
              [str(v) for v in ds.body_name.values] == ['platform'],
              (line_names, point_names))
        check('system: a long_name on every variable, units on every number',
              all(ds[k].attrs.get('long_name') for k in ds.variables) and
              all(ds[k].attrs.get('units') for k in ds.variables if ds[k].dtype != object),
              [k for k in ds.variables if not ds[k].attrs.get('long_name')])
        bad = []
        for r, row in enumerate(points):
            t, p = divmod(r, len(point_names))
            want = tuple(row[k] for k in ('t', 'x', 'y', 'z', 'fx', 'fy', 'fz'))
            have = (fmt10(ds.time.values[t]),) + tuple(
                fmt12(ds[f'point_{c}'].values[t, p]) for c in 'xyz') + tuple(
                fmt10(ds[f'point_f{c}'].values[t, p]) for c in 'xyz')
            if want != have:
                bad.append((r, want, have))
        check('system: every row of points.csv', not bad, bad[:3])
        bad = []
        for i, line in enumerate(line_names):
            series = table('lines', line, 'timeseries.csv')
            end = int(ds.line_end_point.values[i])
            for t, row in enumerate(series):
                want = tuple(row[k] for k in ('tension_start', 'tension_end', 'tension_max',
                                              'link_max', 'x_end', 'y_end', 'z_end'))
                have = tuple(fmt10(ds[k].values[t, i]) for k in
                             ('tension_start', 'tension_end', 'tension_max')) + (
                    str(int(ds.link_max.values[t, i])),) + tuple(
                    fmt12(ds[f'point_{c}'].values[t, end]) for c in 'xyz')
                if want != have:
                    bad.append((line, t, want, have))
        check('system: each line\'s timeseries.csv, its end at its line_end_point', not bad,
              bad[:3])
        bad = []
        for t, row in enumerate(bodies):
            want = tuple(row[k] for k in ('x', 'y', 'z', 'rx', 'ry', 'rz', 'fx', 'fy', 'fz',
                                          'mx', 'my', 'mz'))
            have = tuple(fmt12(ds[f'body_{c}'].values[t, 0]) for c in 'xyz') + tuple(
                fmt10(ds[f'body_{k}{c}'].values[t, 0]) for k in 'rfm' for c in 'xyz')
            if want != have:
                bad.append((t, want, have))
        check('system: every row of body.csv', not bad, bad[:3])

    failed = 0
    for name, ok, detail in results:
        print(('ok    ' if ok else 'FAIL  ') + name + ('' if ok else f': {detail}'))
        failed += not ok
    print(f'{len(results) - failed} passed, {failed} failed')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
