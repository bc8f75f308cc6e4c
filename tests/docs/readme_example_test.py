#!/usr/bin/python3
"""The README's first scene (docs/recipes/first_scene.toml) says what `cablefilm check` and
`cablefilm run` print for it: this runs both and holds every figure the README quotes to what
they print, rounded as the README rounds it (the README once said 1800 steps for a run that had
come to take 2012).

    /usr/bin/python3 tests/docs/readme_example_test.py --cablefilm build/cablefilm \\
        --source-dir . --out-dir /tmp/readme_example
"""
import argparse
import pathlib
import re
import subprocess
import sys


def find(pattern, text, what):
    """The groups of pattern's first match in text; fails naming what was looked for."""
    m = re.search(pattern, text, flags=re.S)
    if not m:
        sys.exit(f'FAIL: {what}: no match for {pattern!r}')
    return m.groups()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--cablefilm', required=True)
    ap.add_argument('--source-dir', required=True)
    ap.add_argument('--out-dir', required=True)
    args = ap.parse_args()
    source = pathlib.Path(args.source_dir)
    readme = re.sub(r'\s+', ' ', (source / 'README.md').read_text())
    scene = source / 'docs' / 'recipes' / 'first_scene.toml'

    def run(*command):
        p = subprocess.run([args.cablefilm, *command], capture_output=True, text=True,
                           timeout=120)
        if p.returncode != 0:
            sys.exit(f'FAIL: cablefilm {" ".join(command)} exited {p.returncode}: {p.stderr}')
        return p.stdout + p.stderr

    check = run('check', str(scene))
    result = run('run', str(scene), '--no-film', '--out', args.out_dir)
    failures = []

    def same(what, documented, printed):
        print(f'{what}: README {documented}, program {printed}')
        if documented != printed:
            failures.append(f'{what}: the README says {documented}, the program prints {printed}')

    # The check's paragraph.
    stations, links, length, weight = find(
        r'prints the cable \((\d+) stations, (\d+) links, ([\d.]+) m, a net weight in water of '
        r'([\d.]+) N\)', readme, 'README: the cable')
    same('stations and links', (stations, links),
         find(r'(\d+) stations, (\d+) links', check, 'check: stations'))
    same('length [m]', length, find(r'unstretched length ([\d.]+) m', check, 'check: length')[0])
    same('net weight [N]', weight, find(r'net weight in fluid ([\d.]+) N', check, 'check: weight')[0])
    limit_ms, = find(r'stability limit \(([\d.]+) ms\)', readme, 'README: stability limit')
    printed_s, = find(r'stable time step of the explicit scheme ([\d.e+-]+) s', check,
                      'check: stable step')
    same('explicit limit [ms]', limit_ms, f'{float(printed_s) * 1e3:.2f}')
    tolerance_mm, = find(r'tolerance ([\d.]+) mm\)', readme, 'README: tolerance')
    printed_m, = find(r'tolerance ([\d.e+-]+) m:', check, 'check: tolerance')
    same('tolerance [mm]', float(tolerance_mm), round(float(printed_m) * 1e3, 9))
    iterations, = find(r'finds the static equilibrium \((\d+) Newton iterations\)', readme,
                       'README: statics')
    same('statics iterations', iterations,
         find(r'static equilibrium found: (\d+) Newton iterations', check, 'check: statics')[0])
    # The run's paragraph.
    anchor, buoy = find(r'gives (\d+) N at the anchor and (\d+) N at the buoy', readme,
                        'README: end tensions')
    start, end = find(r'tension ([\d.]+) N at the start, ([\d.]+) N at the end', result,
                      'run: end tensions')
    same('end tensions [N]', (int(anchor), int(buoy)), (round(float(start)), round(float(end))))
    steps, = find(r'simulates the 60 s in (\d+) steps', readme, 'README: steps')
    same('steps', steps, find(r'simulated 60 s in [\d.e+-]+ s of computer time \([\d.e+-]+ s of CPU\): (\d+) steps',
                              result, 'run: steps')[0])
    peak, = find(r'prints `(peak tension [^`]+)`', readme, 'README: peak')
    same('peak line', peak, find(r'(peak tension [\d.]+ N at t = [\d.]+ s in link \d+)', result,
                                 'run: peak')[0])
    if failures:
        print('\n'.join('FAIL: ' + f for f in failures))
        sys.exit(1)
    print('README example: every figure as the program prints it')


if __name__ == '__main__':
    main()
