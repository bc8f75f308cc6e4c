#!/usr/bin/python3
"""Benchmark of `cablefilm live`: the server's CPU use with 0, 1 and 3 WebSocket viewers at
720p and 1080p, frames delivered, real time, and control-to-frame latency. Prints its figures
and the machine's load; asserts nothing.

    /usr/bin/python3 bench/bench_live.py [--cablefilm build/cablefilm] [--sizes 1280x720,1920x1080]
        [--viewers 0,1,3] [--seconds 10] [--latency-trials 30] [--rolling]

CPU: the server process's user + system time over the window (/proc/PID/stat), in cores, with
the given number of viewers connected (0: nobody watching; issue 23 item 5 asks for no drawing
then, and under 0.4 cores at 1080p with 3 viewers).
Frames per viewer: every binary WebSocket message counted over the window, per viewer.
kB/frame: the JPEG's mean size (the message less its 24-byte header).
Real time: simulated seconds advanced per wall second (/state t).
Latency (with the most viewers of the largest size): a control (the amplitude alternating
1.00/1.01) is POSTed to /control; its answer carries the control's sequence number; the time
until the first frame whose header carries that number (or a later one) arrives at a viewer.
--rolling: measured once t is past the scene's duration (reached at 10x speed), when the time
plot's window rolls with the clock and its axis moves every frame (before, only its newest
samples change): the steady state of a view left open.
Load: os.getloadavg() before and after each window (1, 5, 15 min): the other work on the
machine, which the figures share its cores with.
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


class Server:
    def __init__(self, binary, scene, size):
        self.proc = subprocess.Popen([binary, 'live', scene, '--port', '0', '--size', size,
                                      '--out', '/tmp/cablefilm-bench-live'],
                                     stdout=subprocess.PIPE, text=True)
        self.base = None
        while self.base is None:
            line = self.proc.stdout.readline()
            if not line:
                raise SystemExit('the server did not start')
            m = re.match(r'live view at (http://\S+)/', line)
            self.base = m.group(1) if m else None
        self.ticks = os.sysconf('SC_CLK_TCK')

    def state(self):
        with urllib.request.urlopen(self.base + '/state') as r:
            return json.loads(r.read())

    def control(self, body):
        req = urllib.request.Request(self.base + '/control', data=json.dumps(body).encode(), method='POST')
        with urllib.request.urlopen(req) as r:
            return json.loads(r.read())

    def cpu_seconds(self):
        with open(f'/proc/{self.proc.pid}/stat') as f:
            fields = f.read().rsplit(')', 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / self.ticks

    def stop(self):
        self.proc.terminate()
        self.proc.wait(timeout=30)


class Viewers:
    """`n` WebSocket viewers, each on a thread counting its frames and the newest sequence."""

    def __init__(self, base, n):
        self.counts = [0] * n
        self.bytes = [0] * n
        self.seen_seq = [0] * n
        self.waiting_for = None
        self.event = threading.Event()
        self.stop = threading.Event()
        self.threads = [threading.Thread(target=self.run, args=(base, i), daemon=True) for i in range(n)]
        for t in self.threads:
            t.start()

    def run(self, base, i):
        ws = websocket.create_connection(base.replace('http', 'ws') + '/ws')
        while not self.stop.is_set():
            op, data = ws.recv_data()
            if op != websocket.ABNF.OPCODE_BINARY:
                continue
            self.counts[i] += 1
            self.bytes[i] += len(data) - 24
            self.seen_seq[i] = struct.unpack('<QdQ', data[:24])[2]
            if self.waiting_for is not None and self.seen_seq[i] >= self.waiting_for:
                self.event.set()
        ws.close()

    def close(self):
        self.stop.set()
        for t in self.threads:
            t.join(timeout=5)


def load():
    return '%.2f %.2f %.2f' % os.getloadavg()


def measure(srv, n, seconds):
    viewers = Viewers(srv.base, n)
    time.sleep(2.0)  # warm up: every viewer connected and receiving
    l0 = load()
    c0, w0, s0, n0, b0 = srv.cpu_seconds(), time.time(), srv.state(), list(viewers.counts), sum(viewers.bytes)
    time.sleep(seconds)
    c1, w1, s1, n1, b1 = srv.cpu_seconds(), time.time(), srv.state(), list(viewers.counts), sum(viewers.bytes)
    wall = w1 - w0
    return viewers, {
        'cores': (c1 - c0) / wall,
        'drawn': (s1['frame'] - s0['frame']) / wall,
        'fps': [(n1[i] - n0[i]) / wall for i in range(n)],
        'realtime': (s1['t'] - s0['t']) / wall,
        'kb': (b1 - b0) / 1000 / max(1, sum(n1) - sum(n0)),
        'wall': wall,
        'load': (l0, load()),
    }


def latency(srv, viewers, trials):
    out = []
    for k in range(trials):
        viewers.event.clear()
        t_send = time.perf_counter()
        reply = srv.control({'amplitude_scale': 1.01 if k % 2 == 0 else 1.0})
        viewers.waiting_for = reply['seq']
        if any(s >= reply['seq'] for s in viewers.seen_seq):
            viewers.event.set()
        viewers.event.wait(5)
        out.append((time.perf_counter() - t_send) * 1000)
        viewers.waiting_for = None
        time.sleep(0.4)  # fewer than SmoothSchedule::kMaxRamps changes ramping at once
    return sorted(out)


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--cablefilm', default='build/cablefilm')
    p.add_argument('--scene', default='scenes/polachek1963.toml')
    p.add_argument('--sizes', default='1280x720,1920x1080')
    p.add_argument('--viewers', default='0,1,3', help='viewer counts to measure, comma-separated')
    p.add_argument('--seconds', type=float, default=10)
    p.add_argument('--latency-trials', type=int, default=30)
    p.add_argument('--rolling', action='store_true',
                   help="measure once the time plot's window rolls (t past the scene's duration)")
    a = p.parse_args()
    sizes = a.sizes.split(',')
    counts = [int(v) for v in a.viewers.split(',')]
    print(f'cablefilm live {a.scene}: server CPU with WebSocket viewers ({a.seconds:g} s windows); '
          f'{os.cpu_count()} cores, load average {load()} at start'
          + (", the time window rolling" if a.rolling else ", the time window filling"))
    print(f'  {"size":>9} {"viewers":>7} {"cores":>6} {"drawn/s":>7} {"real time":>9}  '
          f'{"frames/s per viewer":<22} {"kB/frame":>8}  load 1/5/15 min before -> after')
    lat = None
    for size in sizes:
        srv = Server(a.cablefilm, a.scene, size)
        try:
            if a.rolling:  # at 10x until the window is full, then real time again
                srv.control({'speed': 10})
                while srv.state()['t'] < srv.state()['duration'] + 2:
                    time.sleep(0.2)
                srv.control({'speed': 1})
            for n in counts:
                viewers, r = measure(srv, n, a.seconds)
                fps = ', '.join(f'{f:.1f}' for f in r['fps']) or '-'
                print(f'  {size:>9} {n:>7} {r["cores"]:>6.3f} {r["drawn"]:>7.1f} {r["realtime"]:>9.3f}  '
                      f'{fps:<22} {r["kb"]:>8.1f}  {r["load"][0]} -> {r["load"][1]}', flush=True)
                if size == sizes[-1] and n == max(counts) and n > 0 and a.latency_trials > 0:
                    lat = (size, n, latency(srv, viewers, a.latency_trials))
                viewers.close()
        finally:
            srv.stop()
    if lat:
        size, n, ms = lat
        print(f'  control -> frame showing it ({size}, {n} viewers): median {statistics.median(ms):.1f} ms, '
              f'90th percentile {ms[int(0.9 * (len(ms) - 1))]:.1f} ms, max {ms[-1]:.1f} ms ({len(ms)} trials)')
    print(f'  load average at the end: {load()}')


if __name__ == '__main__':
    main()
