#!/usr/bin/python3
"""Benchmark of a long line's run (issue 23, item 3): case P63 with each of its two sections cut
into --segments links (default 3000: 6000 links of 1.5 cm), 60 s simulated, through the whole
`cablefilm run SCENE --no-film` with every result file it writes. Prints for each run the
simulation's time as the run reports it, its steps and Newton iterations, the whole process's
CPU (user + system, wait4's accounting) and wall time, the size of results.nc, and the machine's
load; then the medians. Asserts nothing.

    /usr/bin/python3 bench/bench_long_line.py [--cablefilm build/cablefilm]
        [--segments 3000] [--runs 3] [--against OTHER/cablefilm]

With --against, the runs of the two programs alternate (on a shared machine the load moves
between them alike) and the medians of both and their ratio are printed.

Issue 23 asks for the simulation in 1.5 s and the whole run in 2.5 s of CPU at 6000 links.
"""
import argparse
import os
import pathlib
import re
import statistics
import tempfile
import time

SOURCE = pathlib.Path(__file__).resolve().parent.parent


def long_scene(folder, segments):
    """scenes/polachek1963.toml with both sections' `segments` set: its path."""
    text = (SOURCE / 'scenes' / 'polachek1963.toml').read_text()
    text, count = re.subn(r'^segments = \d+', f'segments = {segments}', text, flags=re.M)
    if count != 2:
        raise SystemExit(f'expected two sections in scenes/polachek1963.toml, found {count}')
    path = pathlib.Path(folder) / f'p63_{2 * segments}.toml'
    path.write_text(text)
    return path


def run_once(program, scene, out):
    """One `run --no-film`: a dict of its figures."""
    log = pathlib.Path(out) / 'run.log'
    t0 = time.monotonic()
    with open(log, 'w') as f:
        pid = os.posix_spawn(program, [program, 'run', str(scene), '--no-film', '--out', str(out)],
                             os.environ, file_actions=[(os.POSIX_SPAWN_DUP2, f.fileno(), 1),
                                                       (os.POSIX_SPAWN_DUP2, f.fileno(), 2)])
        _, status, usage = os.wait4(pid, 0)
    wall = time.monotonic() - t0
    text = log.read_text(errors='replace')
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f'{program} run {scene} failed:\n{text}')
    sim = re.search(r'simulated \S+ s in \S+ s of computer time \((\S+) s of CPU\): (\d+) steps '
                    r'\((\d+) rejected\).*?, (\S+) Newton iterations per step', text)
    if not sim:
        raise SystemExit(f'no "simulated ..." line in the output of {program}:\n{text}')
    return {'simulation': float(sim.group(1)), 'steps': int(sim.group(2)),
            'rejected': int(sim.group(3)), 'newton': float(sim.group(4)),
            'cpu': usage.ru_utime + usage.ru_stime, 'wall': wall,
            'nc_mb': (pathlib.Path(out) / 'results.nc').stat().st_size / 1e6,
            'load': os.getloadavg()[0]}


def show(name, r):
    print(f'{name}: simulation {r["simulation"]:.3f} s ({r["steps"]} steps, {r["rejected"]} '
          f'rejected, {r["newton"]:.2f} Newton iterations a step), process CPU {r["cpu"]:.3f} s, '
          f'wall {r["wall"]:.3f} s, results.nc {r["nc_mb"]:.1f} MB; load {r["load"]:.2f}',
          flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--cablefilm', default=str(SOURCE / 'build' / 'cablefilm'))
    parser.add_argument('--segments', type=int, default=3000)
    parser.add_argument('--runs', type=int, default=3)
    parser.add_argument('--against', help='another cablefilm, run in turn with this one')
    args = parser.parse_args()
    programs = [os.path.abspath(args.cablefilm)]
    if args.against:
        programs.append(os.path.abspath(args.against))
    with tempfile.TemporaryDirectory() as tmp:
        scene = long_scene(tmp, args.segments)
        print(f'case P63 at {2 * args.segments} links, 60 s: `cablefilm run {scene.name} '
              f'--no-film`; load average {os.getloadavg()[0]:.2f}', flush=True)
        results = {p: [] for p in programs}
        for k in range(args.runs):
            for p in programs:
                out = pathlib.Path(tmp) / f'out{programs.index(p)}'
                out.mkdir(exist_ok=True)
                results[p].append(run_once(p, scene, out))
                show(f'run {k + 1} {p}', results[p][-1])
        medians = {}
        for p in programs:
            medians[p] = {key: statistics.median(r[key] for r in results[p])
                          for key in ('simulation', 'cpu', 'wall')}
            m = medians[p]
            print(f'median of {args.runs}, {p}: simulation {m["simulation"]:.3f} s, process CPU '
                  f'{m["cpu"]:.3f} s, wall {m["wall"]:.3f} s (issue 23: 1.5 s and 2.5 s)')
        if len(programs) == 2:
            a, b = (medians[p] for p in programs)
            print(f'this / the other: simulation {a["simulation"] / b["simulation"]:.3f}, '
                  f'CPU {a["cpu"] / b["cpu"]:.3f}, wall {a["wall"] / b["wall"]:.3f}')
    print(f'load average now {os.getloadavg()[0]:.2f}')


if __name__ == '__main__':
    main()
