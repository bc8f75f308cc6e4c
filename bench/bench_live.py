#!/usr/bin/python3
"""Benchmark of `cablefilm live`: frames delivered to several WebSocket viewers, real time,
control-to-frame latency and the server's CPU use. Prints its figures; asserts nothing.

    /usr/bin/python3 bench/bench_live.py [--cablefilm build/cablefilm] [--size 1280x720]
        [--viewers 3] [--seconds 10] [--latency-trials 40]

Frames per viewer: every binary WebSocket message counted over the window, per viewer.
Real time: simulated seconds advanced per wall second (/state t).
Latency: a control (the amplitude alternating 1.00/1.01) is POSTed to /control; its answer
carries the control's sequence number; the time until the first frame whose header carries
that number (or a later one) arrives at a viewer: request to a frame that shows it.
CPU: the server process's user + system time over the window (/proc/PID/stat), in cores.
"""
import argparse
import json
import os
import re
import statistics
import struct
import subprocess
import threading
import time
import urllib.request

import websocket  # Debian's python3-websocket


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--cablefilm', default='build/cablefilm')
    p.add_argument('--scene', default='scenes/polachek1963.toml')
    p.add_argument('--size', default='1280x720')
    p.add_argument('--viewers', type=int, default=3)
    p.add_argument('--seconds', type=float, default=10)
    p.add_argument('--latency-trials', type=int, default=30)
    a = p.parse_args()
    proc = subprocess.Popen([a.cablefilm, 'live', a.scene, '--port', '0', '--size', a.size,
                             '--out', '/tmp/cablefilm-bench-live'],
                            stdout=subprocess.PIPE, text=True)
    base = None
    while base is None:
        line = proc.stdout.readline()
        if not line:
            raise SystemExit('the server did not start')
        m = re.match(r'live view at (http://\S+)/', line)
        base = m.group(1) if m else None

    def state():
        with urllib.request.urlopen(base + '/state') as r:
            return json.loads(r.read())

    def control(body):
        req = urllib.request.Request(base + '/control', data=json.dumps(body).encode(), method='POST')
        with urllib.request.urlopen(req) as r:
            return json.loads(r.read())

    counts = [0] * a.viewers
    seen_seq = [0] * a.viewers
    events = [threading.Event() for _ in range(a.viewers)]
    waiting_for = [None]
    stop = threading.Event()

    def viewer(i):
        ws = websocket.create_connection(base.replace('http', 'ws') + '/ws')
        while not stop.is_set():
            op, data = ws.recv_data()
            if op != websocket.ABNF.OPCODE_BINARY:
                continue
            counts[i] += 1
            seen_seq[i] = struct.unpack('<QdQ', data[:24])[2]
            if waiting_for[0] is not None and seen_seq[i] >= waiting_for[0]:
                events[i].set()
        ws.close()

    threads = [threading.Thread(target=viewer, args=(i,), daemon=True) for i in range(a.viewers)]
    for t in threads:
        t.start()
    time.sleep(2.0)  # warm up: every viewer connected and receiving

    ticks = os.sysconf('SC_CLK_TCK')

    def cpu_seconds():
        with open(f'/proc/{proc.pid}/stat') as f:
            fields = f.read().rsplit(')', 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / ticks

    c0, w0, s0, n0 = cpu_seconds(), time.time(), state()['t'], list(counts)
    time.sleep(a.seconds)
    c1, w1, s1, n1 = cpu_seconds(), time.time(), state()['t'], list(counts)
    wall = w1 - w0
    fps = [(n1[i] - n0[i]) / wall for i in range(a.viewers)]

    latencies = []
    for k in range(a.latency_trials):
        for e in events:
            e.clear()
        t_send = time.perf_counter()
        reply = control({'amplitude_scale': 1.01 if k % 2 == 0 else 1.0})
        waiting_for[0] = reply['seq']
        if any(s >= reply['seq'] for s in seen_seq):
            events[0].set()
        events[0].wait(5)
        latencies.append((time.perf_counter() - t_send) * 1000)
        waiting_for[0] = None
        time.sleep(0.4)  # fewer than SmoothSchedule::kMaxRamps changes ramping at once

    stop.set()
    proc.terminate()
    proc.wait(timeout=30)
    print(f'cablefilm live {a.scene} at {a.size}, {a.viewers} WebSocket viewers, {wall:.1f} s:')
    print('  frames/s delivered per viewer: ' + ', '.join(f'{f:.1f}' for f in fps))
    print(f'  real-time factor: {(s1 - s0) / wall:.3f} (simulated s per wall s)')
    print(f'  server CPU: {(c1 - c0) / wall:.3f} cores (user + system, all threads)')
    lat = sorted(latencies)
    print(f'  control -> frame showing it: median {statistics.median(lat):.1f} ms, '
          f'90th percentile {lat[int(0.9 * (len(lat) - 1))]:.1f} ms, max {lat[-1]:.1f} ms '
          f'({len(lat)} trials)')


if __name__ == '__main__':
    main()
