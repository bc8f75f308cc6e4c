#!/usr/bin/python3
"""Issue 23, item 1: what a process loads. The program links neither the GL and codec stacks
nor libnetcdf; it loads cablefilm_netcdf.so when a run writes results.nc and cablefilm_render.so
when it films (src/modules/). Checked from the ELF header (readelf -d) and from the dynamic
loader's own log of a run (LD_DEBUG=files), and a missing module is a clear error.

    modules_test.py --cablefilm build/cablefilm --scene scenes/polachek1963.toml --out-dir DIR
"""
import argparse
import os
import shutil
import subprocess
import sys

HEAVY = ('libOSMesa', 'libLLVM', 'libavcodec', 'libavformat', 'libswscale', 'libjpeg',
         'libnetcdf', 'libhdf5')  # what takes 25-200 ms to load
failures = []


def check(what, ok, detail=''):
    print(('ok  ' if ok else 'FAIL') + ' ' + what + (f': {detail}' if detail and not ok else ''))
    if not ok:
        failures.append(what)


def loaded(cmd, env=None):
    """The shared objects the dynamic loader opened for `cmd` (its LD_DEBUG=files log)."""
    e = dict(os.environ, **(env or {}), LD_DEBUG='files')
    p = subprocess.run(cmd, env=e, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    names = set()
    for line in p.stderr.splitlines():
        if 'file=' in line and ('[0];  needed by' in line or 'dynamically loaded by' in line
                                or '[0];  generating link map' in line):
            names.add(os.path.basename(line.split('file=')[1].split()[0].rstrip(';')))
    return p, names


def main():
    a = argparse.ArgumentParser()
    a.add_argument('--cablefilm', required=True)
    a.add_argument('--scene', required=True)
    a.add_argument('--out-dir', required=True)
    args = a.parse_args()
    shutil.rmtree(args.out_dir, ignore_errors=True)
    os.makedirs(args.out_dir)

    needed = subprocess.run(['readelf', '-d', args.cablefilm], stdout=subprocess.PIPE,
                            text=True, check=True).stdout
    libs = [l.split('[')[1].split(']')[0] for l in needed.splitlines() if '(NEEDED)' in l]
    check('the program links none of the heavy libraries', not any(
        l.startswith(h) for l in libs for h in HEAVY), libs)

    p, names = loaded([args.cablefilm, '--version'])
    check('--version loads no module and no heavy library', p.returncode == 0 and not any(
        n.startswith(h) or n.startswith('cablefilm_') for n in names for h in HEAVY), sorted(names))

    p, names = loaded([args.cablefilm, 'check', args.scene])
    check('check loads no module', p.returncode == 0 and not any(
        n.startswith('cablefilm_') for n in names), sorted(names))

    out = os.path.join(args.out_dir, 'nofilm')
    p, names = loaded([args.cablefilm, 'run', args.scene, '--no-film', '--out', out])
    check('run --no-film writes every file', p.returncode == 0 and all(
        os.path.isfile(os.path.join(out, f)) for f in
        ('equilibrium.csv', 'timeseries.csv', 'results.nc', 'max_tension.png', 'run_report.toml')),
        p.stdout[-500:])
    check('run --no-film loads the NetCDF module', 'cablefilm_netcdf.so' in names, sorted(names))
    check('run --no-film loads neither the render module nor OSMesa nor libav*',
          'cablefilm_render.so' not in names and not any(
              n.startswith(h) for n in names for h in ('libOSMesa', 'libLLVM', 'libavcodec')),
          sorted(names))

    # A module that is not there: the command says which, and where it looked.
    empty = os.path.join(args.out_dir, 'no_modules')
    os.makedirs(empty)
    p = subprocess.run([args.cablefilm, 'run', args.scene, '--no-film', '--out',
                        os.path.join(args.out_dir, 'missing')],
                       env=dict(os.environ, CABLEFILM_MODULE_DIR=empty),
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    check('a missing module is an error naming it and where it was looked for',
          p.returncode != 0 and 'cablefilm_netcdf.so' in p.stdout and empty in p.stdout
          and 'CABLEFILM_MODULE_DIR' in p.stdout, p.stdout[-600:])
    check('... and leaves no results.nc', not os.path.exists(
        os.path.join(args.out_dir, 'missing', 'results.nc')))

    print('FAIL' if failures else 'ok', f'({len(failures)} failed)' if failures else '')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
