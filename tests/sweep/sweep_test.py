#!/usr/bin/python3
"""cablefilm sweep (issue 12, part 5), end to end, and the Dask example:

    /usr/bin/python3 tests/sweep/sweep_test.py TEST --cablefilm build/cablefilm \\
        --source-dir . --work-dir /tmp/sweep_test

TEST is one of
  cross_product  a 3x3 sweep of case P63 shortened (5 s, 20 links, a row every 0.1 s, no film)
                 gives 9 folders, each scene the original with its values set (to the bit),
                 and a sweep.csv whose peaks, minima, snaps and peak_converged are those of
                 single `cablefilm run`s of the same case scenes (same binary, same inputs:
                 timeseries.csv byte for byte)
  refused        a key not in the scene format, a bad value in one case, an index beyond an
                 array, a bad --set: refused before anything is written or run, naming the
                 key, with the message `check` gives for that case's scene
  cases          --cases CSV (times --set), values of every kind, a motion table's relative
                 file resolved from another folder, a blow-up case in the summary
  moordyn        a MoorDyn file swept over one key of its equivalent scene: each case's scene is
                 the one `cablefilm convert` writes with its value set, each row has the case's
                 results, and the case of the file's own value is `cablefilm run` of the file
  interrupt      SIGINT while a case runs: the finished case stays whole, the running one
                 keeps its rows as .partial and is "interrupted", the rest "not run", exit 130
  dask           examples/dask_sweep.py on a local cluster of two workers writes the same
                 sweep.csv as cablefilm sweep (skipped, exit 77, if dask.distributed is
                 missing: install Debian's python3-distributed, as scripts/setup.sh --tests does)

Prints PASS/FAIL lines and `N passed, M failed`.
"""
import argparse
import csv
import math
import os
import shutil
import signal
import subprocess
import sys
import time
import tomllib

SHORT = ['simulation.duration=5', 'output.interval=0.1', 'cable.section[0].segments=10',
         'cable.section[1].segments=10']
SWEPT = ['environment.current=0,0.25,0.5', 'ends.end.period=8,10,12']
REPORT_KEYS = ['peak_tension', 'peak_time', 'peak_link', 'min_tension', 'min_tension_time',
               'min_tension_link', 'snaps', 'peak_converged',
               *[f'tension_{end}_{name}' for end in ('start', 'end')
                 for name in ('mean', 'std', 'min', 'max', 'upcrossings', 'mpm')]]

passed = failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
        print(f'PASS: {what}')
    else:
        failed += 1
        print(f'FAIL: {what}')
    return ok


def sets(*pairs):
    out = []
    for p in pairs:
        out += ['--set', p]
    return out


def run(args, cwd, **kw):
    started = time.monotonic()
    done = subprocess.run([ARGS.cablefilm, *args], cwd=cwd, capture_output=True, text=True, **kw)
    done.seconds = time.monotonic() - started
    return done


def read_csv(path):
    with open(path, newline='', encoding='utf-8') as f:
        rows = list(csv.reader(f))
    return rows[0], [dict(zip(rows[0], r)) for r in rows[1:]]


def toml_load(path):
    with open(path, 'rb') as f:
        return tomllib.load(f)


def toml_value(text):
    try:
        return tomllib.loads(f'v = {text}')['v']
    except tomllib.TOMLDecodeError:
        return text  # a bare word: a string


def set_key(doc, key, value):
    """Sets a dotted key with [i] indices in a parsed TOML document."""
    parts = key.split('.')
    node = doc
    for i, part in enumerate(parts):
        name, *indices = part.replace(']', '').split('[')
        last = i == len(parts) - 1
        if last and not indices:
            node[name] = value
            return
        node = node.setdefault(name, {})
        for k, index in enumerate(indices):
            if last and k == len(indices) - 1:
                node[int(index)] = value
                return
            node = node[int(index)]


def report_cells(report):
    """run_report.toml's values as sweep.csv prints them."""
    cells = {}
    for key in REPORT_KEYS:
        v = report[key]
        if isinstance(v, bool):
            cells[key] = 'true' if v else 'false'
        elif isinstance(v, int) and (key.endswith('_link') or key.endswith('_upcrossings') or
                                     key == 'snaps'):
            cells[key] = str(v)
        else:
            cells[key] = '%.10g' % float(v)
    return cells


def test_cross_product(work):
    scene = os.path.join(ARGS.source_dir, 'scenes', 'polachek1963.toml')
    out = os.path.join(work, 'sweep')
    done = run(['sweep', scene, *sets(*SHORT, *SWEPT), '--out', out], work)
    if not check(done.returncode == 0, f'the sweep exits 0 ({done.seconds:.2f} s)'):
        print(done.stdout, done.stderr)
        return
    folders = sorted(d for d in os.listdir(out) if os.path.isdir(os.path.join(out, d)))
    check(folders == [f'case_{i:03d}' for i in range(9)], f'9 case folders: {folders}')
    header, rows = read_csv(os.path.join(out, 'sweep.csv'))
    keys = [s.split('=')[0] for s in SHORT + SWEPT]
    check(header == ['case', 'folder', *keys, 'status', 'message', *REPORT_KEYS],
          f'sweep.csv header: {header}')
    check(len(rows) == 9 and all(r['status'] == 'ok' for r in rows),
          'sweep.csv: 9 rows, every case ok')
    expected = [(c, p) for c in ('0', '0.25', '0.5') for p in ('8', '10', '12')]
    check([(r['environment.current'], r['ends.end.period']) for r in rows] == expected,
          'the cross product, the first --set varying slowest')
    original = toml_load(scene)
    for i, row in enumerate(rows):
        folder = os.path.join(out, row['folder'])
        want = toml_load(scene)
        for key in keys:
            set_key(want, key, toml_value(row[key]))
        got = toml_load(os.path.join(folder, 'scene.toml'))
        check(got == want and got != original,
              f'case {i}: scene.toml is the original with its values set, every other value '
              'to the bit')
        single = os.path.join(work, 'single', row['folder'])
        done = run(['run', os.path.join(folder, 'scene.toml'), '--out', single, '--no-film'],
                   work)
        if not check(done.returncode == 0, f'case {i}: a single cablefilm run of its scene'):
            print(done.stderr)
            continue
        report = toml_load(os.path.join(single, 'run_report.toml'))
        cells = report_cells(report)
        check(all(row[k] == cells[k] for k in REPORT_KEYS),
              f'case {i}: sweep.csv equals the single run: peak {row["peak_tension"]} N at '
              f'{row["peak_time"]} s in link {row["peak_link"]}, minimum {row["min_tension"]} N, '
              f'snaps {row["snaps"]}, converged {row["peak_converged"]}')
        with open(os.path.join(folder, 'timeseries.csv'), 'rb') as a, \
                open(os.path.join(single, 'timeseries.csv'), 'rb') as b:
            series = a.read()
            check(series == b.read(), f'case {i}: timeseries.csv byte for byte as the single run')
        lines = series.decode().splitlines()
        cols = lines[0].split(',')
        data = [dict(zip(cols, map(float, line.split(',')))) for line in lines[1:]]
        peak = max(d['tension_max'] for d in data)
        lowest_end = min(min(d['tension_start'], d['tension_end']) for d in data)
        check('%.10g' % peak == row['peak_tension'] and
              float(row['min_tension']) <= lowest_end + 1e-9 * peak,
              f'case {i}: the peak is the largest tension_max of the rows, the minimum at or '
              'below every end tension')


def refused(work, name, set_args, key, status=1):
    out = os.path.join(work, name)
    scene = os.path.join(ARGS.source_dir, 'scenes', 'polachek1963.toml')
    done = run(['sweep', scene, *set_args, '--out', out], work)
    check(done.returncode == status and key in done.stderr and not os.path.exists(out),
          f'{name}: exit {done.returncode}, nothing written, the message names {key}: '
          f'{done.stderr.strip().splitlines()[0] if done.stderr.strip() else "(none)"}')
    return done


def test_refused(work):
    done = refused(work, 'unknown_key', sets('environment.curent=0,1'), 'environment.curent')
    # The same message as `check` on that case's scene: made by hand from a prepared case.
    out = os.path.join(work, 'unknown_key')
    prepared = run(['sweep', os.path.join(ARGS.source_dir, 'scenes', 'polachek1963.toml'),
                    *sets('environment.current=0'), '--out', out, '--prepare'], work)
    path = os.path.join(out, 'case_000', 'scene.toml')
    if check(prepared.returncode == 0, '--prepare writes the case scene'):
        with open(path, encoding='utf-8') as f:
            text = f.read()
        with open(path, 'w', encoding='utf-8') as f:
            f.write(text.replace('environment.current', 'environment.curent')
                    .replace('current = 0', 'curent = 0'))
        checked = run(['check', path], work)
        said = checked.stderr.strip().removeprefix('cablefilm: error: ')
        check(checked.returncode == 1 and said and done.stderr.strip().endswith(said),
              f'the sweep says what check says of that scene: {said}')
    refused(work, 'bad_value', sets('environment.current=0,fast'), 'environment.current')
    refused(work, 'bad_in_one_case', sets('environment.current=0,0.5', 'ends.end.period=10,-1'),
            'ends.end.period')
    refused(work, 'index_beyond', sets('material[2].youngs_modulus=1e9'),
            'material[2].youngs_modulus')
    refused(work, 'not_toml', sets('ends.end.x_amplitudes=[1,0],[2'), 'ends.end.x_amplitudes', 2)
    refused(work, 'no_values', sets('environment.current'), '--set', 2)
    refused(work, 'nothing', [], 'nothing to sweep', 2)
    # Ranges A..B: a usage error naming the key.
    refused(work, 'range_down', sets('cable.section[0].segments=5..1'),
            'cable.section[0].segments', 2)
    refused(work, 'range_not_whole', sets('cable.section[0].segments=1..x'),
            'cable.section[0].segments', 2)
    refused(work, 'range_too_long', sets('cable.section[0].segments=1..20000'),
            'cable.section[0].segments', 2)


def test_seeds(work):
    """A range A..B of a whole-number key, and the Gumbel fit of the cases' maxima
    (sweep_maxima.toml) against one made here from sweep.csv's columns."""
    scene = os.path.join(ARGS.source_dir, 'scenes', 'polachek1963.toml')
    out = os.path.join(work, 'sweep')
    done = run(['sweep', scene, *sets(*SHORT[:3], 'cable.section[1].segments=8..11'),
                '--summary-only', '--out', out], work)
    if not check(done.returncode == 0, f'the sweep exits 0 ({done.seconds:.2f} s)'):
        print(done.stdout, done.stderr)
        return
    header, rows = read_csv(os.path.join(out, 'sweep.csv'))
    check([r['cable.section[1].segments'] for r in rows] == ['8', '9', '10', '11'],
          '8..11: four cases, 8, 9, 10 and 11 segments')
    maxima = toml_load(os.path.join(out, 'sweep_maxima.toml'))
    gamma = 0.5772156649015329
    for column in ('peak_tension', 'tension_start_max', 'tension_end_max'):
        x = [float(r[column]) for r in rows]
        n = len(x)
        mean = sum(x) / n
        std = math.sqrt(sum((v - mean) ** 2 for v in x) / (n - 1))
        beta = std * math.sqrt(6) / math.pi
        mu = mean - gamma * beta
        p90 = mu - beta * math.log(-math.log(0.9))
        got = maxima[column]
        check(got['cases'] == [0, 1, 2, 3] and got['maxima'] == x,
              f'{column}: the maxima of the four cases as sweep.csv has them: {x}')
        check(all(abs(got[k] - v) <= 1e-8 * abs(v) + 1e-9 * mean for k, v in
                  (('mean', mean), ('std', std), ('gumbel_beta', beta), ('gumbel_mu', mu),
                   ('gumbel_p90', p90))),
              f'{column}: Gumbel fit mu {got["gumbel_mu"]} N, beta {got["gumbel_beta"]} N, '
              f'p90 {got["gumbel_p90"]} N (here: {mu:.10g}, {beta:.10g}, {p90:.10g})')
        check(f'{column}: Gumbel fit of 4 maxima: most probable maximum (mode) ' in done.stdout,
              f'{column}: the fit printed')
    # Two cases: their maxima, no fit.
    out2 = os.path.join(work, 'two')
    done = run(['sweep', scene, *sets(*SHORT[:3], 'cable.section[1].segments=8..9'),
                '--summary-only', '--out', out2], work)
    two = toml_load(os.path.join(out2, 'sweep_maxima.toml'))
    check(done.returncode == 0 and len(two['peak_tension']['maxima']) == 2 and
          'gumbel_mu' not in two['peak_tension'] and 'Gumbel' not in done.stdout,
          'two cases: their maxima, no Gumbel fit')


def test_cases(work):
    scene = os.path.join(ARGS.source_dir, 'scenes', 'polachek1963.toml')
    cases = os.path.join(work, 'cases.csv')
    with open(cases, 'w', encoding='utf-8') as f:
        f.write('environment.current, ends.end.x_amplitudes ,simulation.integrator\n'
                '0.1,"[1.0, 0.0]",explicit\n\n'
                '-0.2,"[2, 0.5]","""implicit"""\n'
                '0.3,"[0.0,0.0]",implicit\n')
    out = os.path.join(work, 'prepared')
    done = run(['sweep', scene, '--cases', cases, *sets('ends.end.period=9,11'), '--out', out,
                '--prepare'], work)
    if not check(done.returncode == 0, '--cases with --set, prepared'):
        print(done.stdout, done.stderr)
        return
    header, rows = read_csv(os.path.join(out, 'sweep.csv'))
    check(len(rows) == 6 and all(r['status'] == 'not run' for r in rows),
          '3 rows of cases x 2 values: 6 cases, "not run"')
    want = [('0.1', '9'), ('0.1', '11'), ('-0.2', '9'), ('-0.2', '11'), ('0.3', '9'), ('0.3', '11')]
    check([(r['environment.current'], r['ends.end.period']) for r in rows] == want,
          'each row of the cases times the --set values')
    s3 = toml_load(os.path.join(out, 'case_003', 'scene.toml'))
    check(s3['environment']['current'] == -0.2 and s3['ends']['end']['x_amplitudes'] == [2, 0.5]
          and s3['simulation']['integrator'] == 'implicit' and s3['ends']['end']['period'] == 11,
          'case 3: a negative number, an array, a quoted string, an integer')
    s0 = toml_load(os.path.join(out, 'case_000', 'scene.toml'))
    check(s0['simulation']['integrator'] == 'explicit', 'a bare word is a string')

    # A motion table's relative file, resolved from another folder.
    table_scene = os.path.relpath(os.path.join(ARGS.source_dir, 'scenes', 'ship_table.toml'), work)
    out = os.path.join(work, 'table')
    done = run(['sweep', table_scene, *sets('simulation.duration=1,2'), '--out', 'table',
                '--prepare'], work)
    if check(done.returncode == 0, 'a scene with a motion table, by a relative path'):
        case = toml_load(os.path.join(out, 'case_001', 'scene.toml'))
        file = case['ends']['end']['file']
        check(os.path.isabs(file) and os.path.exists(file), f'its table made absolute: {file}')
        checked = run(['check', os.path.join(out, 'case_001', 'scene.toml')], '/')
        check(checked.returncode == 0, 'the case scene checks from another folder')

    # A case that blows up (an explicit step 9 times its stability limit) beside one that runs.
    out = os.path.join(work, 'blowup')
    done = run(['sweep', scene, *sets('simulation.duration=1', 'simulation.integrator=explicit',
                                      'simulation.time_step=auto,0.01'), '--out', out], work)
    header, rows = read_csv(os.path.join(out, 'sweep.csv'))
    check(done.returncode == 1 and [r['status'] for r in rows] == ['ok', 'blow-up'] and
          'blow-up' in rows[1]['message'] and rows[1]['peak_tension'] == '' and
          rows[0]['peak_tension'] != '',
          f'a blow-up is a row with its message, the sweep exits 1: {rows[1]["message"][:80]}...')


def test_moordyn(work):
    leg = os.path.join(ARGS.source_dir, 'tests', 'scenes', 'moordyn', 'one_leg.txt')
    out = os.path.join(work, 'sweep')
    # The chain's 50 kg/m (the file's) and twice that.
    done = run(['sweep', leg, *sets('material[0].mass_per_length=50,100'), '--out', out], work)
    if not check(done.returncode == 0, f'the sweep of a MoorDyn file exits 0 ({done.seconds:.2f} s)'):
        print(done.stdout, done.stderr)
        return
    header, rows = read_csv(os.path.join(out, 'sweep.csv'))
    check(header == ['case', 'folder', 'material[0].mass_per_length', 'status', 'message',
                     *REPORT_KEYS], f'sweep.csv header: {header}')
    check([(r['material[0].mass_per_length'], r['status']) for r in rows] ==
          [('50', 'ok'), ('100', 'ok')], f'one row per case, each ok: {rows}')
    converted = run(['convert', leg], work)
    check(converted.returncode == 0, 'cablefilm convert of the file')
    for row in rows:
        want = tomllib.loads(converted.stdout)
        set_key(want, 'material[0].mass_per_length', toml_value(row['material[0].mass_per_length']))
        got = toml_load(os.path.join(out, row['folder'], 'scene.toml'))
        check(got == want, f'case {row["case"]}: scene.toml is the converted scene with its value set')
    # The file's own value: the file's own run, row for row.
    single = os.path.join(work, 'single')
    done = run(['run', leg, '--no-film', '--out', single], work)
    if check(done.returncode == 0, 'cablefilm run of the MoorDyn file'):
        cells = report_cells(toml_load(os.path.join(single, 'run_report.toml')))
        check(all(rows[0][k] == cells[k] for k in REPORT_KEYS),
              f'case 0 is the file\'s run: peak {rows[0]["peak_tension"]} N, minimum '
              f'{rows[0]["min_tension"]} N (the run: {cells["peak_tension"]}, {cells["min_tension"]})')
        with open(os.path.join(out, 'case_000', 'timeseries.csv'), 'rb') as a, \
                open(os.path.join(single, 'timeseries.csv'), 'rb') as b:
            check(a.read() == b.read(), 'case 0: timeseries.csv byte for byte as the file\'s run')
    # Twice the chain's weight: its fairlead carries more than its first, every row.
    peaks = [float(r['peak_tension']) for r in rows]
    lows = [float(r['min_tension']) for r in rows]
    check(peaks[0] > 1e4 and 1.9 * peaks[0] < peaks[1] < 2.5 * peaks[0] and lows[1] > lows[0] > 0,
          f'the heavier chain is the more loaded: peaks {peaks} N, minima {lows} N')


def test_interrupt(work):
    scene = os.path.join(ARGS.source_dir, 'scenes', 'polachek1963.toml')
    cases = os.path.join(work, 'cases.csv')
    with open(cases, 'w', encoding='utf-8') as f:
        # The second case: 600 links explicit for 60 s, about half a minute: stopped early.
        f.write('simulation.integrator,simulation.duration\nimplicit,2\nexplicit,60\nimplicit,2\n')
    out = os.path.join(work, 'sweep')
    proc = subprocess.Popen([ARGS.cablefilm, 'sweep', scene, '--cases', cases,
                             *sets('cable.section[0].segments=300', 'cable.section[1].segments=300'),
                             '--out', out, '--jobs', '1'],
                            cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    # Its equilibrium.csv is written when its simulation starts.
    started = os.path.join(out, 'case_001', 'equilibrium.csv')
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None and not os.path.exists(started):
        time.sleep(0.02)
    time.sleep(0.2)
    proc.send_signal(signal.SIGINT)
    output, _ = proc.communicate(timeout=120)
    header, rows = read_csv(os.path.join(out, 'sweep.csv'))
    statuses = [r['status'] for r in rows]
    check(proc.returncode == 130 and statuses == ['ok', 'interrupted', 'not run'],
          f'SIGINT: exit {proc.returncode}, statuses {statuses}')
    c0, c1, c2 = (sorted(os.listdir(os.path.join(out, f'case_00{i}'))) for i in range(3))
    check('timeseries.csv' in c0 and 'run_report.toml' in c0, f'the finished case whole: {c0}')
    check('timeseries.partial.csv' in c1 and 'timeseries.csv' not in c1,
          f'the running case keeps its rows as .partial: {c1}')
    check(c2 == ['scene.toml'], f'the case not started holds its scene only: {c2}')
    if failed:
        print(output)


def test_summary_only(work):
    """--summary-only (issue 23): the cases run on threads of the sweep's own process and only
    sweep.csv is written; its rows are those of the sweep with case folders (the same runs:
    the same doubles), with an empty folder column, and an earlier sweep's case folders go.
    A SIGINT stops it as it stops a sweep of processes."""
    scene = os.path.join(ARGS.source_dir, 'scenes', 'polachek1963.toml')
    out, folders = os.path.join(work, 'summary'), os.path.join(work, 'folders')
    done = run(['sweep', scene, *sets(*SHORT, *SWEPT), '--out', folders], work)
    check(done.returncode == 0, f'the sweep with case folders exits 0 ({done.seconds:.2f} s)')
    with_folders = done.seconds
    done = run(['sweep', scene, *sets(*SHORT, *SWEPT), '--out', folders, '--summary-only'], work)
    if not check(done.returncode == 0, f'--summary-only exits 0 ({done.seconds:.2f} s, '
                 f'{with_folders / done.seconds:.2g} times faster)'):
        print(done.stdout, done.stderr)
        return
    # Beside it the folder's list of what the sweep wrote (docs/cli.md: what a run removes).
    left = sorted(os.listdir(folders))
    check(left == ['.cablefilm.written', 'sweep.csv', 'sweep_maxima.toml'],
          f'--summary-only leaves sweep.csv and sweep_maxima.toml alone: {left}')
    listed = open(os.path.join(folders, '.cablefilm.written')).read().split('\n')[1:]
    check(listed == ['sweep.csv', 'sweep_maxima.toml', ''],
          f'and its list names them alone: {listed}')
    done = run(['sweep', scene, *sets(*SHORT, *SWEPT), '--out', out], work)
    _, rows_folders = read_csv(os.path.join(out, 'sweep.csv'))
    _, rows_summary = read_csv(os.path.join(folders, 'sweep.csv'))
    for a, b in zip(rows_folders, rows_summary):
        a['folder'] = ''
    check(rows_folders == rows_summary and len(rows_summary) == 9,
          'every row as the sweep with case folders, the folder column empty')
    refused_film = run(['sweep', scene, *sets(*SWEPT), '--summary-only', '--film', '--out', out],
                       work)
    check(refused_film.returncode == 1 and 'summary-only' in refused_film.stderr,
          f'--summary-only with --film is refused: {refused_film.stderr.strip()}')

    cases = os.path.join(work, 'cases.csv')
    with open(cases, 'w', encoding='utf-8') as f:
        f.write('simulation.integrator,simulation.duration\nimplicit,2\nexplicit,60\nimplicit,2\n')
    stopped = os.path.join(work, 'stopped')
    proc = subprocess.Popen([ARGS.cablefilm, 'sweep', scene, '--cases', cases, '--summary-only',
                             *sets('cable.section[0].segments=300',
                                   'cable.section[1].segments=300'),
                             '--out', stopped, '--jobs', '1'],
                            cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seen = []
    for line in proc.stdout:  # case 0 ends in a second or two; case 1 then runs for a while
        seen.append(line)
        if line.startswith('case 0 '):
            break
    time.sleep(1.0)
    proc.send_signal(signal.SIGINT)
    output, _ = proc.communicate(timeout=120)
    _, rows = read_csv(os.path.join(stopped, 'sweep.csv'))
    statuses = [r['status'] for r in rows]
    check(proc.returncode == 130 and statuses == ['ok', 'interrupted', 'not run'],
          f'SIGINT: exit {proc.returncode}, statuses {statuses}')
    if failed:
        print(''.join(seen), output)


def test_dask(work):
    try:
        import dask.distributed  # noqa: F401
    except ImportError as e:
        print(f'SKIP: dask.distributed is not importable ({e}); install Debian\'s '
              'python3-distributed (scripts/setup.sh --tests does)')
        sys.exit(77)
    scene = os.path.join(ARGS.source_dir, 'scenes', 'polachek1963.toml')
    cpp = os.path.join(work, 'cablefilm')
    done = run(['sweep', scene, *sets(*SHORT, *SWEPT), '--out', cpp, '--jobs', '2'], work)
    check(done.returncode == 0, f'cablefilm sweep ({done.seconds:.2f} s)')
    example = os.path.join(ARGS.source_dir, 'examples', 'dask_sweep.py')
    started = time.monotonic()
    dask = subprocess.run([sys.executable, example, scene, *sets(*SHORT, *SWEPT), '--out',
                           os.path.join(work, 'dask'), '--cablefilm', ARGS.cablefilm,
                           '--workers', '2'],
                          cwd=work, capture_output=True, text=True, timeout=300)
    seconds = time.monotonic() - started
    if not check(dask.returncode == 0, f'examples/dask_sweep.py, a local cluster of two workers '
                 f'({seconds:.2f} s)'):
        print(dask.stdout, dask.stderr)
        return
    check('on 2 workers' in dask.stdout, 'two workers')
    _, a = read_csv(os.path.join(cpp, 'sweep.csv'))
    _, b = read_csv(os.path.join(work, 'dask', 'sweep.csv'))
    check(len(b) == 9 and [r['peak_tension'] for r in a] == [r['peak_tension'] for r in b],
          'the same peaks: ' + ', '.join(r['peak_tension'] for r in b))
    with open(os.path.join(cpp, 'sweep.csv'), 'rb') as f, \
            open(os.path.join(work, 'dask', 'sweep.csv'), 'rb') as g:
        check(f.read() == g.read(), 'the same sweep.csv, byte for byte')
    check(all(os.path.exists(os.path.join(work, 'dask', r['folder'], 'timeseries.csv'))
              for r in b), 'each case ran in its folder')
    # The cases' maxima and their Gumbel fit, as cablefilm sweep gives them (the same 10 digits
    # of each maximum; the fit's sums may round apart in the last bit, then print within 1e-9).
    ours = toml_load(os.path.join(cpp, 'sweep_maxima.toml'))
    theirs = toml_load(os.path.join(work, 'dask', 'sweep_maxima.toml'))
    for column in ('peak_tension', 'tension_start_max', 'tension_end_max'):
        a, b = ours[column], theirs.get(column, {})
        check(a['cases'] == b.get('cases') and a['maxima'] == b.get('maxima') and
              all(abs(b.get(k, 0) - a[k]) <= 1e-9 * abs(a[k]) for k in
                  ('mean', 'std', 'gumbel_beta', 'gumbel_mu', 'gumbel_p90')),
              f'{column}: the maxima and their Gumbel fit as cablefilm sweep\'s: {b}')
    check('peak_tension: Gumbel fit of 9 maxima: most probable maximum (mode) ' in dask.stdout,
          'the example prints the fit')


def main():
    global ARGS
    parser = argparse.ArgumentParser()
    parser.add_argument('test', choices=['cross_product', 'refused', 'cases', 'moordyn', 'interrupt',
                                         'summary_only', 'seeds', 'dask'])
    parser.add_argument('--cablefilm', required=True)
    parser.add_argument('--source-dir', required=True)
    parser.add_argument('--work-dir', required=True)
    ARGS = parser.parse_args()
    ARGS.cablefilm = os.path.abspath(ARGS.cablefilm)
    ARGS.source_dir = os.path.abspath(ARGS.source_dir)
    work = os.path.abspath(ARGS.work_dir)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    globals()[f'test_{ARGS.test}'](work)
    print(f'{passed} passed, {failed} failed')
    sys.exit(1 if failed else 0)


if __name__ == '__main__':
    main()
