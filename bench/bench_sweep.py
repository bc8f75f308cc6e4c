#!/usr/bin/python3
"""Benchmark of many runs (issue 23, item 2): N cases of case P63 (its current swept over N
values) by `cablefilm sweep --jobs J` with case folders, by `cablefilm sweep --summary-only`,
and by the Python module's `sweep(jobs=J)`. Prints the wall time of each (median of --repeat
runs), their ratios and the machine's load; asserts nothing.

    /usr/bin/python3 bench/bench_sweep.py [--cablefilm build/cablefilm] [--python-dir build/python]
        [--cases 100] [--jobs 2] [--repeat 3]

Issue 23 asks for the command-line sweep within 1.5 times Python's: with case folders every
case is a process that writes its files (timeseries.csv, results.nc, max_tension.png); with
--summary-only only sweep.csv is written.
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--cablefilm', default='build/cablefilm')
    p.add_argument('--python-dir', default='build/python')
    p.add_argument('--scene', default='scenes/polachek1963.toml')
    p.add_argument('--cases', type=int, default=100)
    p.add_argument('--jobs', type=int, default=2)
    p.add_argument('--repeat', type=int, default=3)
    a = p.parse_args()
    currents = ','.join('%.4g' % (0.5 * i / max(1, a.cases - 1)) for i in range(a.cases))
    work = tempfile.mkdtemp(prefix='cablefilm-bench-sweep-')
    print(f'load before: {os.getloadavg()}')

    def cli(*extra):
        out = os.path.join(work, 'sweep')
        t0 = time.monotonic()
        subprocess.run([a.cablefilm, 'sweep', a.scene, '--set', f'environment.current={currents}',
                        '--jobs', str(a.jobs), '--out', out, '--no-film', *extra],
                       check=True, capture_output=True)
        seconds = time.monotonic() - t0
        shutil.rmtree(out)
        return seconds

    def python():
        code = ('import sys, time; sys.path.insert(0, sys.argv[1]); import cablefilm; '
                's = cablefilm.load(sys.argv[2]); t0 = time.monotonic(); '
                'cablefilm.sweep(s, {"environment.current": [float(v) for v in '
                'sys.argv[3].split(",")]}, jobs=int(sys.argv[4])); print(time.monotonic() - t0)')
        t0 = time.monotonic()
        subprocess.run(['/usr/bin/python3', '-c', code, a.python_dir, a.scene, currents,
                        str(a.jobs)], check=True, capture_output=True, text=True)
        return time.monotonic() - t0

    figures = {}
    for name, measure in (('sweep, case folders', cli), ('sweep --summary-only',
                                                          lambda: cli('--summary-only')),
                          ('Python sweep()', python)):
        times = [measure() for _ in range(a.repeat)]
        figures[name] = statistics.median(times)
        print(f'{name}: {a.cases} cases, --jobs {a.jobs}: median {figures[name]:.2f} s '
              f'(min {min(times):.2f}, max {max(times):.2f}, {a.repeat} runs; the Python figure '
              'includes starting the interpreter)')
    py = figures['Python sweep()']
    for name in ('sweep, case folders', 'sweep --summary-only'):
        print(f'{name} / Python: {figures[name] / py:.2f}')
    print(f'load after: {os.getloadavg()}')
    shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
