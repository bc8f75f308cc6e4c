#!/usr/bin/python3
"""results.nc in xarray (issue 12, part 3): `xarray.open_dataset("results.nc")` opens it with no
extra arguments, and its dimensions, units and values agree with timeseries.csv and
equilibrium.csv, as those print them.

    /usr/bin/python3 tests/app/netcdf_xarray_test.py --cablefilm build/cablefilm \\
        --scene scenes/polachek1963.toml --out-dir /tmp/netcdf_xarray

Runs case P63 cut to 5 s without its film. Exits 77 (skipped, with a message) when xarray or
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
    text = open(a.scene).read()
    text = re.sub(r'^duration = .*$', 'duration = 5.0', text, flags=re.M)
    scene = os.path.join(a.out_dir, 'p63_short.toml')
    with open(scene, 'w') as f:
        f.write(text)
    out = os.path.join(a.out_dir, 'out')
    done = subprocess.run([a.cablefilm, 'run', scene, '--no-film', '--out', out],
                          capture_output=True, text=True)
    if done.returncode != 0:
        print(f'FAIL  cablefilm run: exit {done.returncode}: {done.stderr.strip()[-500:]}')
        print('0 passed, 1 failed')
        return 1

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
        units = {'time': 's', 'x': 'm', 'y': 'm', 'tension': 'N', 's': 'm', 's_link': 'm',
                 'x_start': 'm', 'y_start': 'm', 'x_end': 'm', 'y_end': 'm',
                 'x_equilibrium': 'm', 'y_equilibrium': 'm', 'tension_equilibrium': 'N'}
        got = {k: ds[k].attrs.get('units') for k in units}
        check('units', got == units, got)
        names = list(ds.variables)
        check('a long_name on every variable', all(ds[k].attrs.get('long_name') for k in names),
              [k for k in names if not ds[k].attrs.get('long_name')])
        check('dims of x, y, tension',
              (ds.x.dims, ds.y.dims, ds.tension.dims) ==
              (('time', 'station'), ('time', 'station'), ('time', 'link')),
              (ds.x.dims, ds.y.dims, ds.tension.dims))
        check('arc lengths are coordinates', 's' in ds.x.coords and 's_link' in ds.tension.coords,
              list(ds.coords))
        check('Conventions', ds.attrs.get('Conventions') == 'CF-1.8', ds.attrs.get('Conventions'))
        check('title', ds.attrs.get('title') == 'Sample mooring line, Polachek et al. 1963',
              ds.attrs.get('title'))
        check('the scene text', ds.attrs.get('scene') == text)
        check('the program version', str(ds.attrs.get('cablefilm_version', '')).startswith('0.'),
              ds.attrs.get('cablefilm_version'))
        enc = ds.x.encoding
        check('x deflated and shuffled', enc.get('zlib') and enc.get('complevel') == 4 and
              enc.get('shuffle'), {k: enc.get(k) for k in ('zlib', 'complevel', 'shuffle')})
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
            want = (row['t'], row['x_end'], row['y_end'], row['tension_start'],
                    row['tension_end'], row['tension_max'], row['link_max'])
            have = (fmt10(ds.time.values[r]), fmt12(ds.x_end.values[r]),
                    fmt12(ds.y_end.values[r]), fmt10(tension[r, 0]), fmt10(tension[r, -1]),
                    fmt10(tmax[r]), str(int(link_max[r])))
            if want != have:
                bad.append((r, want, have))
        check('every row of timeseries.csv (t, x_end, y_end, start, end, max, link_max)',
              not bad, bad[:3])
        check('x_end, y_end are the last station', np.array_equal(ds.x_end, ds.x[:, -1]) and
              np.array_equal(ds.y_end, ds.y[:, -1]))
        check('x_start, y_start are the first station', np.array_equal(ds.x_start, ds.x[:, 0])
              and np.array_equal(ds.y_start, ds.y[:, 0]))
        # One link at one time, by label, against the CSV's tension_start at t = 2 s.
        row = next(r for r in rows if r['t'] == '2')
        check('tension.sel(time=2, link=0) is tension_start at t = 2',
              fmt10(ds.tension.sel(time=2.0, link=0, method='nearest')) == row['tension_start'],
              (float(ds.tension.sel(time=2.0, link=0, method='nearest')), row['tension_start']))
        # The equilibrium against equilibrium.csv.
        bad = []
        for j, row in enumerate(eq):
            have = (fmt10(ds.s.values[j]), fmt12(ds.x_equilibrium.values[j]),
                    fmt12(ds.y_equilibrium.values[j]),
                    fmt10(ds.tension_equilibrium.values[j]) if j < 60 else '')
            if have != (row['s'], row['x'], row['y'], row['tension']):
                bad.append((j, row, have))
        check('equilibrium.csv (s, x, y, tension)', not bad, bad[:3])
        check('the first row is the equilibrium',
              np.array_equal(ds.x[0], ds.x_equilibrium) and np.array_equal(ds.y[0],
                                                                         ds.y_equilibrium))
        check('s_link is the link midpoints',
              np.allclose(ds.s_link, 0.5 * (ds.s.values[:-1] + ds.s.values[1:]), rtol=0,
                          atol=1e-12))

    failed = 0
    for name, ok, detail in results:
        print(('ok    ' if ok else 'FAIL  ') + name + ('' if ok else f': {detail}'))
        failed += not ok
    print(f'{len(results) - failed} passed, {failed} failed')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
