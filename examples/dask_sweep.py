#!/usr/bin/python3
"""A cablefilm sweep on a Dask cluster: the cases of `cablefilm sweep`, each `cablefilm run` as
a Dask task, and the same summary table, DIR/sweep.csv.

    /usr/bin/python3 examples/dask_sweep.py scenes/polachek1963.toml \\
        --set environment.current=0,0.25,0.5 --set ends.end.period=8,10,12 \\
        [--cases CASES.csv] [--out DIR] [--scheduler tcp://HOST:8786] [--workers 2] \\
        [--cablefilm PATH] [-- RUN OPTIONS, e.g. --film --size 640x360]

1. The cases are built by cablefilm itself, `cablefilm sweep ... --prepare`: the cross product
   of the --set values (or the rows of --cases), each case's scene checked as `cablefilm check`
   would (a bad key or value stops here, naming it, before anything runs), written to
   DIR/case_NNN/scene.toml, and DIR/sweep.csv with every case "not run". So they are the very
   cases `cablefilm sweep` runs.
2. Dask maps the cases over the cluster: a local one, LocalCluster(n_workers=2,
   threads_per_worker=1) (--workers), or the scheduler at --scheduler. Each task runs
   `cablefilm run DIR/case_NNN/scene.toml --out DIR/case_NNN --no-film [RUN OPTIONS]` as a
   subprocess (its output in the case's run.log) and returns its row from run_report.toml.
3. The client writes DIR/sweep.csv (atomically: a temporary file renamed), with the columns
   and the number formats of `cablefilm sweep`, and DIR/sweep_maxima.toml as it does: the
   finished cases' maxima of peak_tension, tension_start_max and tension_end_max and, from 3 of
   them, their Gumbel fit (DNV-OS-E301's most probable maximum of a storm run with several
   seeds: `--set waves.seed=1..10`).

On a real cluster the workers need `cablefilm` (--cablefilm: its path on the workers, default
the one found here) and DIR on a file system they share with the client (the paths are made
absolute). Ctrl-C cancels the cases not yet started and writes the summary of those finished;
the cases already running on the workers finish (Dask does not stop a task's subprocess).

Needs Debian's python3-distributed (`apt-get install python3-distributed`).
"""
import argparse
import csv
import math
import os
import shutil
import signal
import subprocess
import sys
import tomllib

# After the case, folder and value columns of sweep.csv (as cablefilm sweep writes them).
RESULT_COLUMNS = ['status', 'message', 'peak_tension', 'peak_time', 'peak_link', 'min_tension',
                  'min_tension_time', 'min_tension_link', 'snaps', 'peak_converged',
                  *[f'tension_{end}_{name}' for end in ('start', 'end')
                    for name in ('mean', 'std', 'min', 'max', 'upcrossings', 'mpm')]]
REPORT_KEYS = RESULT_COLUMNS[2:]


def number(value):
    """A number as sweep.csv prints it: whole numbers (links, snaps, up-crossings) as they are,
    the others with 10 significant digits, as run_report.toml has them."""
    return '%.10g' % float(value)


def last_message(log_path):
    """The last line the run printed about what stopped it, without 'cablefilm: [error: ]'."""
    last = ''
    try:
        with open(log_path, encoding='utf-8', errors='replace') as log:
            for line in log:
                line = line.rstrip('\r\n')
                if line.startswith('cablefilm: '):
                    last = line[len('cablefilm: '):]
    except OSError:
        pass
    return last[len('error: '):] if last.startswith('error: ') else last


def summarize(folder, returncode):
    """The status, message and results of a finished `cablefilm run` in `folder` (the rules of
    cablefilm sweep: ok with a run_report.toml; blow-up when it failed with the rows so far in
    timeseries.partial.csv; else error)."""
    row = {'status': 'error', 'message': ''}
    if returncode == 0:
        try:
            with open(os.path.join(folder, 'run_report.toml'), 'rb') as f:
                report = tomllib.load(f)
        except (OSError, tomllib.TOMLDecodeError):
            report = None
        if report is not None:
            for key in REPORT_KEYS:
                value = report.get(key)
                if isinstance(value, bool):
                    row[key] = 'true' if value else 'false'
                elif isinstance(value, int) and (key.endswith('_link') or
                                                 key.endswith('_upcrossings') or key == 'snaps'):
                    row[key] = str(value)
                elif isinstance(value, (int, float)):
                    row[key] = number(value)
                else:
                    row[key] = ''
            row['status'] = 'ok'
            if row.get('peak_converged') == 'false':
                row['message'] = 'the peak tension is not converged (see run_report.toml)'
            return row
    said = last_message(os.path.join(folder, 'run.log'))
    if returncode == 1 and os.path.exists(os.path.join(folder, 'timeseries.partial.csv')):
        row.update(status='blow-up', message=said)
    elif said:
        row['message'] = said
    elif returncode == 0:
        row['message'] = 'no run_report.toml'
    elif returncode > 0:
        row['message'] = f'exit status {returncode}'
    else:
        row['message'] = f'killed by signal {-returncode} ({signal.strsignal(-returncode)})'
    return row


def run_case(folder, cablefilm, run_options):
    """One Dask task: `cablefilm run` on the case in `folder`, its output in run.log."""
    with open(os.path.join(folder, 'run.log'), 'wb') as log:
        done = subprocess.run([cablefilm, 'run', os.path.join(folder, 'scene.toml'), '--out',
                               folder, *run_options],
                              stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT)
    return summarize(folder, done.returncode)


# Euler's constant: the mean of a Gumbel distribution is mu + GAMMA beta.
GAMMA = 0.5772156649015329
MAXIMA_COLUMNS = ['peak_tension', 'tension_start_max', 'tension_end_max']


def gumbel_fit(maxima):
    """The Gumbel (type I extreme value) fit of `maxima` [N] by the method of moments, as
    cablefilm sweep makes it: F(x) = exp(-exp(-(x - mu) / beta)), beta = std sqrt(6) / pi,
    mu = mean - GAMMA beta (the mode: the most probable maximum), and its 90 % quantile."""
    n = len(maxima)
    mean = sum(maxima) / n
    std = math.sqrt(sum((x - mean) ** 2 for x in maxima) / (n - 1))
    beta = std * math.sqrt(6) / math.pi
    mu = mean - GAMMA * beta
    return {'mean': mean, 'std': std, 'gumbel_beta': beta, 'gumbel_mu': mu,
            'gumbel_p90': mu - beta * math.log(-math.log(0.9))}


def write_maxima(path, rows, header):
    """sweep_maxima.toml, as cablefilm sweep writes it, whole or not at all; returns the lines
    that describe the fits."""
    said = []
    text = ('# cablefilm sweep: the maxima of the finished cases and, from 3 of them, their '
            'Gumbel fit\n# (method of moments: beta = std sqrt(6) / pi, mu = mean - 0.5772 beta; '
            'F(x) =\n# exp(-exp(-(x - mu) / beta)))\n')
    status = header.index('status')
    for column in MAXIMA_COLUMNS:
        at = header.index(column)
        cases = [i for i, row in enumerate(rows) if row[status] == 'ok' and row[at] != '' and
                 math.isfinite(float(row[at]))]
        maxima = [float(rows[i][at]) for i in cases]
        text += (f'\n[{column}]\ncases = [{", ".join(str(i) for i in cases)}]\nmaxima = ['
                 f'{", ".join(number(x) for x in maxima)}]  # [N], case by case\n')
        if len(maxima) < 3:
            continue
        fit = gumbel_fit(maxima)
        text += (f'mean = {number(fit["mean"])}  # [N], of the maxima\n'
                 f'std = {number(fit["std"])}  # [N], their sample standard deviation (over n - 1)\n'
                 f'gumbel_beta = {number(fit["gumbel_beta"])}  # [N], scale\n'
                 f'gumbel_mu = {number(fit["gumbel_mu"])}  # [N], location: the mode, the most '
                 f'probable maximum\n'
                 f'gumbel_p90 = {number(fit["gumbel_p90"])}  # [N], the 90 % quantile, mu - beta '
                 f'ln(-ln 0.9)\n')
        said.append(f'{column}: Gumbel fit of {len(maxima)} maxima: most probable maximum (mode) '
                    f'{number(fit["gumbel_mu"])} N, 90 % quantile {number(fit["gumbel_p90"])} N '
                    f'(mean {number(fit["mean"])} N, std {number(fit["std"])} N)')
    temp = f'{path}.tmp{os.getpid()}'
    with open(temp, 'w', encoding='utf-8') as f:
        f.write(text)
    os.replace(temp, path)
    return said


def write_summary(path, header, rows):
    """sweep.csv whole or not at all: a temporary file renamed over it."""
    temp = f'{path}.tmp{os.getpid()}'
    with open(temp, 'w', newline='', encoding='utf-8') as f:
        writer = csv.writer(f, lineterminator='\n')
        writer.writerow(header)
        writer.writerows(rows)
    os.replace(temp, path)


def main():
    parser = argparse.ArgumentParser(
        description='cablefilm sweep on a Dask cluster',
        epilog='Options after -- go to each case\'s cablefilm run (e.g. -- --film --size 640x360).')
    parser.add_argument('scene')
    parser.add_argument('--set', action='append', default=[], metavar='KEY=V1,V2,...')
    parser.add_argument('--cases', metavar='CASES.csv')
    parser.add_argument('--out', metavar='DIR', help='default output/<scene name>_sweep')
    parser.add_argument('--scheduler', metavar='ADDRESS',
                        help='a running Dask scheduler (default: a local cluster)')
    parser.add_argument('--workers', type=int, default=2,
                        help='workers of the local cluster, one thread each (default 2)')
    parser.add_argument('--cablefilm', default=shutil.which('cablefilm') or 'cablefilm',
                        help='the program (default: cablefilm on the PATH)')
    argv = sys.argv[1:]
    cut = argv.index('--') if '--' in argv else len(argv)
    args = parser.parse_args(argv[:cut])
    run_options = ['--no-film', *argv[cut + 1:]]  # the film off unless --film comes after
    cablefilm = os.path.abspath(args.cablefilm) if os.sep in args.cablefilm else args.cablefilm
    out = args.out or os.path.join(
        'output', os.path.splitext(os.path.basename(args.scene))[0] + '_sweep')

    # 1. The cases, by cablefilm: checked, written, listed in sweep.csv as "not run".
    prepare = [cablefilm, 'sweep', args.scene, '--out', out, '--prepare']
    for s in args.set:
        prepare += ['--set', s]
    if args.cases:
        prepare += ['--cases', args.cases]
    done = subprocess.run(prepare)
    if done.returncode != 0:
        return done.returncode
    summary = os.path.join(out, 'sweep.csv')
    with open(summary, newline='', encoding='utf-8') as f:
        table = list(csv.reader(f))
    header, cases = table[0], table[1:]
    values = header.index('status')  # the value columns are header[2:values]
    folders = [os.path.abspath(os.path.join(out, case[1])) for case in cases]

    # 2. The cases over the cluster.
    from dask.distributed import Client, LocalCluster, as_completed
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    print(f'dask: {len(cases)} cases on {len(client.scheduler_info()["workers"])} workers '
          f'({client.scheduler.address})', flush=True)
    futures = client.map(run_case, folders, cablefilm=cablefilm, run_options=run_options,
                         pure=False)
    index = {f.key: i for i, f in enumerate(futures)}
    results = {}
    failed = 0
    interrupted = False
    try:
        for future in as_completed(futures):
            i = index[future.key]
            row = results[i] = future.result()
            failed += row['status'] != 'ok'
            described = ', '.join(f'{k} = {v}' for k, v in zip(header[2:values], cases[i][2:values]))
            outcome = (f"ok, peak {row['peak_tension']} N at t = {row['peak_time']} s in link "
                       f"{row['peak_link']}" if row['status'] == 'ok'
                       else f"{row['status']}: {row['message']}")
            print(f'case {i} ({described}): {outcome} [{len(results)}/{len(cases)} done, '
                  f'{failed} failed]', flush=True)
    except KeyboardInterrupt:
        interrupted = True
        client.cancel(futures)
        print('dask: interrupted; the cases not started are cancelled', file=sys.stderr)
    client.close()

    # 3. The summary, as cablefilm sweep writes it.
    rows = []
    for i, case in enumerate(cases):
        row = results.get(i, {'status': 'not run', 'message': ''})
        rows.append(case[:values] + [row.get(c, '') for c in RESULT_COLUMNS])
    write_summary(summary, header, rows)
    maxima = os.path.join(out, 'sweep_maxima.toml')
    for line in write_maxima(maxima, rows, header):
        print(line)
    print(f'wrote {summary} and {maxima}')
    if interrupted:
        return 130
    return 0 if failed == 0 else 1


if __name__ == '__main__':
    sys.exit(main())
