#!/usr/bin/python3
"""Signals at random moments of a run with its film (issue 11, defect 4): whatever stops the
program, a final name holds a complete result of this run or nothing, an incomplete result
carries ".partial" in its name and opens (a film plays up to its last frame), and no result of
an earlier run sits beside the new ones.

    /usr/bin/python3 tests/app/signals_test.py --cablefilm build/cablefilm --scene scenes/polachek1963.toml \\
        --out-dir /tmp/signals [--runs 9] [--seed 1]

Each run goes into a folder that already holds the results of another scene (stale files of
every name a run writes, listed in the folder's ledger as that run listed them). The times are drawn from a seeded generator over the whole run
(simulation, film pass, the still), so the test is repeatable. Prints one line per run and
`N passed, M failed`.
"""
import argparse
import os
import random
import re
import shutil
import signal
import struct
import subprocess
import sys
import time

RESULTS = ['equilibrium.csv', 'timeseries.csv', 'timeseries.partial.csv', 'film.mp4',
           'film.partial.mp4', 'max_tension.png', 'max_tension.partial.png', 'results.nc',
           'results.partial.nc']
STALE = b'stale result of an earlier run'
LEDGER = '.cablefilm.written'  # what the last run in a folder wrote there (docs/cli.md)


def boxes(data, start, end):
    i = start
    while i + 8 <= end:
        size, kind = struct.unpack('>I4s', data[i:i + 8])
        header = 8
        if size == 1:
            size, header = struct.unpack('>Q', data[i + 8:i + 16])[0], 16
        elif size == 0:
            size = end - i
        if size < header or i + size > end:
            return  # a box cut short by SIGKILL ends the readable part
        yield kind, i + header, i + size
        i += size


def mp4_frames(path):
    """Frames of an MP4: from the index (stsz) of an ordinary film, or summed over the
    fragments (trun) of a fragmented one. Raises ValueError if it is no MP4."""
    with open(path, 'rb') as f:
        data = f.read()
    top = list(boxes(data, 0, len(data)))
    kinds = [k for k, _, _ in top]
    if b'ftyp' not in kinds or b'moov' not in kinds:
        raise ValueError(f'{path}: no ftyp/moov ({kinds[:6]})')

    def find(path_, start, end):
        for k, s, e in boxes(data, start, end):
            if k == path_[0]:
                return (s, e) if len(path_) == 1 else find(path_[1:], s, e)
        return None

    frames = 0
    moov = [(s, e) for k, s, e in top if k == b'moov'][0]
    stsz = find([b'trak', b'mdia', b'minf', b'stbl', b'stsz'], *moov)
    if stsz:
        frames = struct.unpack('>I', data[stsz[0] + 8:stsz[0] + 12])[0]
    for k, s, e in top:
        if k != b'moof':
            continue
        for kk, ss, ee in boxes(data, s, e):
            if kk == b'traf':
                trun = find([b'trun'], ss, ee)
                if trun:
                    frames += struct.unpack('>I', data[trun[0] + 4:trun[0] + 8])[0]
    # A fragment's samples count only if its media data is all there.
    mdat_end = max((e for k, _, e in top if k == b'mdat'), default=0)
    if frames and mdat_end == 0:
        raise ValueError(f'{path}: frames but no media data')
    return frames


def png_ok(path):
    with open(path, 'rb') as f:
        data = f.read()
    return data[:8] == b'\x89PNG\r\n\x1a\n' and data.rstrip(b'\x00').endswith(b'IEND\xaeB`\x82')


def nc_rows(path):
    """Rows (the time dimension) of a results file; raises ValueError if it does not open. Without
    Python's netCDF4 module only its HDF5 signature is checked (None)."""
    with open(path, 'rb') as f:
        if f.read(8) != b'\x89HDF\r\n\x1a\n':
            raise ValueError('no HDF5 signature')
    try:
        import netCDF4
    except ImportError:
        return None
    try:
        with netCDF4.Dataset(path) as ds:
            return len(ds.dimensions['time'])
    except (OSError, KeyError) as e:
        raise ValueError(str(e))


def check_folder(folder, expected_rows, expected_frames, killed):
    problems = []
    names = set(os.listdir(folder))
    present = [n for n in RESULTS if n in names]
    if killed and present and all(open(os.path.join(folder, n), 'rb').read(64).startswith(STALE)
                                  for n in present):
        # SIGKILL before the run cleared the folder (the process still starting, say): the
        # earlier results sit there untouched and whole, with nothing new beside them.
        return []
    for name in RESULTS:
        path = os.path.join(folder, name)
        if name not in names:
            continue
        with open(path, 'rb') as f:
            head = f.read(64)
        if head.startswith(STALE):
            problems.append(f'{name} is a stale result of the earlier run')
            continue
        if name == 'timeseries.csv':
            rows = open(path).read().splitlines()
            if len(rows) != expected_rows + 1:
                problems.append(f'timeseries.csv has {len(rows) - 1} rows, not {expected_rows}')
        elif name == 'timeseries.partial.csv':
            rows = open(path).read().splitlines()
            if not rows or not rows[0].startswith('t,'):
                problems.append('timeseries.partial.csv has no header')
        elif name == 'film.mp4':
            n = mp4_frames(path)
            if n != expected_frames:
                problems.append(f'film.mp4 has {n} frames, not {expected_frames}')
        elif name == 'film.partial.mp4':
            try:
                n = mp4_frames(path)
            except ValueError as e:
                problems.append(f'film.partial.mp4 does not open: {e}')
                continue
            if n > expected_frames:
                problems.append(f'film.partial.mp4 has {n} frames, more than the film')
        elif name in ('results.nc', 'results.partial.nc'):
            try:
                n = nc_rows(path)
            except ValueError as e:
                problems.append(f'{name} does not open: {e}')
                continue
            if name == 'results.nc' and n is not None and n != expected_rows:
                problems.append(f'results.nc has {n} rows, not {expected_rows}')
            if name == 'results.partial.nc' and n is not None and n > expected_rows:
                problems.append(f'results.partial.nc has {n} rows, more than the run')
        elif name.endswith('.png') and not png_ok(path):
            problems.append(f'{name} is not a whole PNG')
    for name in names - {LEDGER}:
        if name.startswith('.') or '.tmp' in name:
            if not killed:  # SIGKILL may leave a temporary file; a clean stop may not
                problems.append(f'temporary file {name} left behind')
    if 'film.mp4' in names and 'film.partial.mp4' in names:
        problems.append('both film.mp4 and film.partial.mp4')
    if 'results.nc' in names and 'results.partial.nc' in names:
        problems.append('both results.nc and results.partial.nc')
    return problems


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--cablefilm', required=True)
    p.add_argument('--scene', required=True)
    p.add_argument('--out-dir', required=True)
    p.add_argument('--runs', type=int, default=9)
    p.add_argument('--seed', type=int, default=1)
    a = p.parse_args()
    rng = random.Random(a.seed)
    duration, fps = 20.0, 30
    # A shortened P63 (20 s: 601 rows and frames) at a small film size, so a run takes ~2 s.
    text = open(a.scene).read()
    text = re.sub(r'^duration = .*$', f'duration = {duration}', text, flags=re.M)
    os.makedirs(a.out_dir, exist_ok=True)
    scene = os.path.join(a.out_dir, 'short.toml')
    with open(scene, 'w') as f:
        f.write(text)
    expected = int(duration * fps) + 1
    cmd = [a.cablefilm, 'run', scene, '--size', '320x180']

    # How long a whole run takes here (for the random times), and that it is whole.
    folder = os.path.join(a.out_dir, 'whole')
    shutil.rmtree(folder, ignore_errors=True)
    t0 = time.time()
    done = subprocess.run(cmd + ['--out', folder], capture_output=True, text=True)
    whole = time.time() - t0
    results = []
    problems = check_folder(folder, expected, expected, False) if done.returncode == 0 else [done.stderr]
    for name in ('film.mp4', 'timeseries.csv', 'max_tension.png', 'equilibrium.csv', 'results.nc'):
        if not os.path.exists(os.path.join(folder, name)):
            problems.append(f'a whole run wrote no {name}')
    results.append(('whole run', problems))

    sigs = [signal.SIGINT, signal.SIGTERM, signal.SIGKILL]
    for k in range(a.runs):
        sig = sigs[k % 3]
        at = rng.uniform(0.02, 1.1 * whole)
        folder = os.path.join(a.out_dir, f'run{k}')
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(os.path.join(folder, 'frames'))
        for name in RESULTS:  # an earlier run of another scene left every result
            with open(os.path.join(folder, name), 'wb') as f:
                f.write(STALE)
        with open(os.path.join(folder, LEDGER), 'w') as f:  # and listed them, as runs do
            f.write(''.join(name + '\n' for name in RESULTS))
        proc = subprocess.Popen(cmd + ['--out', folder], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True)
        time.sleep(at)
        proc.send_signal(sig)
        try:
            out, err = proc.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            proc.kill()
            results.append((f'{sig.name} at {at:.2f} s', ['did not stop within 60 s']))
            continue
        problems = check_folder(folder, expected, expected, sig == signal.SIGKILL)
        code = proc.returncode
        if sig != signal.SIGKILL and code not in (0, 128 + sig.value):
            problems.append(f'exit status {code}: {err.strip()[-300:]}')
        results.append((f'{sig.name} at {at:.2f} s (exit {code})', problems))

    failed = 0
    for name, problems in results:
        print(('ok    ' if not problems else 'FAIL  ') + name + ('' if not problems else ': ' + '; '.join(problems)))
        failed += bool(problems)
    print(f'{len(results) - failed} passed, {failed} failed')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
