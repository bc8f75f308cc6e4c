#!/usr/bin/python3
"""Benchmark of a process's fixed cost (issue 23, item 1): the CPU time (user + system, wait4's
accounting) and wall time of a process of `cablefilm --version`, `cablefilm check SCENE` and
`cablefilm run SCENE --no-film` (every result file but the film), beside the simulation's own
time that the run prints, and the machine's load. Asserts nothing.

    /usr/bin/python3 bench/bench_startup.py [--cablefilm build/cablefilm]
        [--scene scenes/polachek1963.toml] [--batches 7] [--against OTHER/cablefilm]

With --against, the batches of the two programs alternate (on a shared machine the load moves
between them alike) and each case prints both medians and their ratio, this one / the other.

Issue 23 asks for --version under 10 ms and a run whose simulation takes 35 ms under 80 ms of
CPU in all.
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import tempfile
import time


def measure(cmd, batches, per_batch):
    """CPU ms per process (median of the batches' means, min, max) and wall ms, and the output
    of `cmd`: each batch runs it `per_batch` times in one /bin/sh loop, reaped by wait4, whose
    accounting is that of the shell and its children alone (a fork of dash: tens of
    microseconds), not of this Python's fork (about 5 ms)."""
    script = 'for i in $(seq %d); do "$@" >"$LOG" 2>&1 || exit 1; done' % per_batch
    cpu, wall = [], []
    with tempfile.NamedTemporaryFile() as log:
        env = dict(os.environ, LOG=log.name)
        for _ in range(batches):
            t0 = time.monotonic()
            pid = os.posix_spawn('/bin/sh', ['/bin/sh', '-c', script, 'sh'] + cmd, env)
            _, status, usage = os.wait4(pid, 0)
            wall.append((time.monotonic() - t0) / per_batch)
            if os.waitstatus_to_exitcode(status) != 0:
                raise SystemExit(f'{cmd} failed:\n{open(log.name).read()}')
            cpu.append((usage.ru_utime + usage.ru_stime) / per_batch)
        out = open(log.name, errors='replace').read()
    return (1e3 * statistics.median(cpu), 1e3 * min(cpu), 1e3 * max(cpu),
            1e3 * statistics.median(wall), out)


def compare(cases, other, batches):
    """Each case's batches of this program and of `other` in turn: both medians, the ratio."""
    for name, cmd, per_batch in cases:
        cpu = {0: [], 1: []}
        for _ in range(batches):
            for k, program in ((0, cmd[0]), (1, other)):
                cpu[k].append(measure([program] + cmd[1:], 1, per_batch)[0])
        this, that = statistics.median(cpu[0]), statistics.median(cpu[1])
        print(f'{name:15s} CPU {this:7.1f} ms a process against {that:7.1f} ms: '
              f'{this / that:.2f} (medians of {batches} alternating batches of {per_batch})')


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--cablefilm', default='build/cablefilm')
    p.add_argument('--scene', default='scenes/polachek1963.toml')
    p.add_argument('--batches', type=int, default=7)
    p.add_argument('--against', help='another build of cablefilm, run in turn with this one')
    a = p.parse_args()
    work = tempfile.mkdtemp(prefix='cablefilm-bench-startup-')
    print(f'load before: {os.getloadavg()}')
    cases = [('--version', [a.cablefilm, '--version'], 40),
             ('check', [a.cablefilm, 'check', a.scene], 40),
             ('run --no-film', [a.cablefilm, 'run', a.scene, '--no-film', '--out',
                                os.path.join(work, 'out')], 3)]
    if a.against:
        compare(cases, a.against, a.batches)
    else:
        for name, cmd, per_batch in cases:
            med, lo, hi, wall, out = measure(cmd, a.batches, per_batch)
            line = (f'{name:15s} CPU {med:7.1f} ms a process (median of {a.batches} batches of '
                    f'{per_batch}; {lo:.1f} to {hi:.1f}), wall {wall:.1f} ms')
            m = re.search(r'simulated [0-9.e+-]+ s in ([0-9.e+-]+) s of computer time', out)
            if m:
                line += f'; the simulation with its sinks {1e3 * float(m.group(1)):.1f} ms (wall)'
            print(line)
    print(f'load after: {os.getloadavg()}')
    shutil.rmtree(work, ignore_errors=True)


if __name__ == '__main__':
    main()
