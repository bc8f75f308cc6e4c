#!/usr/bin/python3
"""End-to-end test of `cablefilm live` over loopback: every endpoint of the interface.

    /usr/bin/python3 tests/live/live_server_test.py --cablefilm ./build/cablefilm \\
        --scene scenes/polachek1963.toml --out-dir /tmp/live-e2e

Starts the server on port 0 and checks: the page and its assets; t advances in real time;
frames arrive at the asked size (JPEG, MJPEG, WebSocket, PNG snapshot); pause stops t and a
single step advances one frame; a current change shows in /state and changes the tensions (on
the scene with its fairlead held still, where nothing else changes them); a bad control answers
400 naming the field and the server keeps serving; a stalled viewer slows nobody; a recording
is a playable MP4 of the frames shown; the time series; SIGTERM exits 0 and closes a recording
in progress. Prints one line per check and `N passed, M failed`; exits 1 on any failure.
Waits poll the state with deadlines instead of sleeping blindly; the deadlines are generous
because the sanitizer build runs the same test several times slower.
"""
import argparse
import json
import os
import re
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

import websocket  # Debian's python3-websocket

READY = re.compile(r'live view at (http://127\.0\.0\.1:(\d+))/\s*$')
WIDTH, HEIGHT = 640, 360


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


class Server:
    def __init__(self, binary, scene, out_dir):
        self.out_dir = out_dir
        self.proc = subprocess.Popen(
            [binary, 'live', scene, '--port', '0', '--size', f'{WIDTH}x{HEIGHT}', '--out', out_dir],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        deadline = time.time() + 60
        self.base = None
        while time.time() < deadline:
            line = self.proc.stdout.readline()
            if not line:
                break
            m = READY.match(line)
            if m:
                self.base, self.port = m.group(1), int(m.group(2))
                break
        if not self.base:
            self.proc.kill()
            raise Failure('no "live view at http://127.0.0.1:PORT/" line: ' + self.proc.stderr.read())

    def get(self, path, timeout=20):
        with urllib.request.urlopen(self.base + path, timeout=timeout) as r:
            return r.status, r.headers, r.read()

    def state(self):
        return json.loads(self.get('/state')[2])

    def control(self, body):
        data = body if isinstance(body, bytes) else json.dumps(body).encode()
        req = urllib.request.Request(self.base + '/control', data=data, method='POST',
                                     headers={'Content-Type': 'application/json'})
        try:
            with urllib.request.urlopen(req, timeout=20) as r:
                return r.status, json.loads(r.read())
        except urllib.error.HTTPError as e:
            return e.code, json.loads(e.read())

    def wait(self, predicate, what, timeout=30):
        deadline = time.time() + timeout
        while time.time() < deadline:
            s = self.state()
            if predicate(s):
                return s
            time.sleep(0.05)
        raise Failure(f'timed out waiting for {what}; last state {json.dumps(s)[:400]}')

    def stop(self):
        self.proc.send_signal(signal.SIGTERM)
        try:
            code = self.proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            raise Failure('SIGTERM did not stop the server within 30 s')
        return code


def jpeg_size(data):
    """(width, height) from a JPEG's SOF marker."""
    check(data[:2] == b'\xff\xd8', 'not a JPEG (no SOI marker)')
    i = 2
    while i + 9 < len(data):
        check(data[i] == 0xff, f'JPEG marker expected at byte {i}')
        marker, length = data[i + 1], struct.unpack('>H', data[i + 2:i + 4])[0]
        if marker in (0xc0, 0xc1, 0xc2):
            h, w = struct.unpack('>HH', data[i + 5:i + 9])
            return w, h
        i += 2 + length
    raise Failure('JPEG without a SOF marker')


def mp4_boxes(data, start=0, end=None):
    end = len(data) if end is None else end
    i = start
    while i + 8 <= end:
        size, kind = struct.unpack('>I4s', data[i:i + 8])
        header = 8
        if size == 1:
            size, header = struct.unpack('>Q', data[i + 8:i + 16])[0], 16
        elif size == 0:
            size = end - i
        check(size >= header and i + size <= end, f'broken MP4 box {kind!r} at {i}')
        yield kind.decode('latin-1'), i + header, i + size
        i += size


def mp4_video(data):
    """(frames, width, height) of the first track of an MP4, read from its boxes."""
    top = {k: (s, e) for k, s, e in mp4_boxes(data)}
    check('moov' in top and 'mdat' in top, f'MP4 lacks moov or mdat: {sorted(top)}')

    def find(path, start, end):
        for kind, s, e in mp4_boxes(data, start, end):
            if kind == path[0]:
                return (s, e) if len(path) == 1 else find(path[1:], s, e)
        raise Failure('MP4 box missing: ' + '/'.join(path))

    s, _ = find(['trak', 'tkhd'], *top['moov'])
    version = data[s]
    off = s + (88 if version == 1 else 76)  # tkhd: the width and height after the matrix
    width, height = (struct.unpack('>I', data[off + k:off + k + 4])[0] >> 16 for k in (0, 4))
    s, _ = find(['trak', 'mdia', 'minf', 'stbl', 'stsz'], *top['moov'])
    frames = struct.unpack('>I', data[s + 8:s + 12])[0]
    return frames, width, height


def run(args):
    results = []
    out_dir = args.out_dir or tempfile.mkdtemp(prefix='cablefilm-live-')

    def step(name, fn):
        try:
            fn()
            results.append((name, None))
            print(f'ok    {name}', flush=True)
        except Failure as e:
            results.append((name, str(e)))
            print(f'FAIL  {name}: {e}', flush=True)
        except Exception as e:  # a broken connection is a failure of the server
            results.append((name, repr(e)))
            print(f'FAIL  {name}: {e!r}', flush=True)

    srv = Server(args.cablefilm, args.scene, out_dir)

    def page():
        status, headers, body = srv.get('/')
        check(status == 200 and b'<html' in body.lower(), 'GET / is not the page')
        check(headers['Content-Type'].startswith('text/html'), 'the page is not text/html')
        for asset, kind in (('/app.js', 'javascript'), ('/style.css', 'text/css')):
            status, headers, body = srv.get(asset)
            check(status == 200 and kind in headers['Content-Type'] and body, asset + ' missing')
        for src in re.findall(rb'(?:src|href)="([^"]+)"', srv.get('/')[2]):
            check(not re.match(rb'(https?:)?//', src), f'the page loads {src!r} from elsewhere')
        try:
            srv.get('/no-such-thing')
            raise Failure('an unknown path answered 200')
        except urllib.error.HTTPError as e:
            check(e.code == 404, f'an unknown path answered {e.code}')

    def real_time():
        s0, w0 = srv.state()['t'], time.time()
        time.sleep(3.0)
        s1, w1 = srv.state()['t'], time.time()
        rate = (s1 - s0) / (w1 - w0)
        # Paced to the wall clock at speed 1; a frame (1/30 s) of jitter at each end.
        check(0.9 < rate < 1.1, f't advanced {s1 - s0:.3f} s in {w1 - w0:.3f} s of wall time')
        st = srv.state()
        for key in ('t', 'paused', 'speed', 'current', 'amplitude_scale', 'period', 'fps'):
            check(key in st, f'/state lacks {key}')
        check(set(st['tension']) >= {'start', 'end', 'max', 'link_max'}, '/state tension keys')
        check(set(st['peak']) >= {'value', 't', 'link'}, '/state peak keys')
        check(st['tension']['max'] >= max(st['tension']['start'], st['tension']['end']),
              'the largest tension is below an end tension')
        check(st['peak']['value'] >= st['tension']['max'] - 1e-6, 'the peak is below the maximum now')

    def frames():
        status, headers, body = srv.get('/frame.jpg')
        check(headers['Content-Type'] == 'image/jpeg', '/frame.jpg is not image/jpeg')
        check(jpeg_size(body) == (WIDTH, HEIGHT), f'/frame.jpg is {jpeg_size(body)}')
        _, headers, png = srv.get('/snapshot.png')
        check(png[:8] == b'\x89PNG\r\n\x1a\n', '/snapshot.png is not a PNG')
        check(struct.unpack('>II', png[16:24]) == (WIDTH, HEIGHT), '/snapshot.png size')
        # MJPEG: two parts, each a JPEG of the size asked, numbered upwards.
        sock = socket.create_connection(('127.0.0.1', srv.port), timeout=20)
        sock.sendall(b'GET /stream.mjpg HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n')
        buf = b''
        while b'\r\n\r\n' not in buf:
            buf += sock.recv(65536)
        head, buf = buf.split(b'\r\n\r\n', 1)
        check(b'Content-Type: multipart/x-mixed-replace; boundary=cablefilmframe' in head,
              f'MJPEG response headers: {head!r}')
        numbers = []
        deadline = time.time() + 20
        while len(numbers) < 2 and time.time() < deadline:
            buf += sock.recv(65536)
            m = re.search(rb'Content-Type: image/jpeg\r\nContent-Length: (\d+)\r\nX-Frame: (\d+)\r\n\r\n', buf)
            if m and len(buf) >= m.end() + int(m.group(1)):
                jpeg = buf[m.end():m.end() + int(m.group(1))]
                check(jpeg_size(jpeg) == (WIDTH, HEIGHT), 'an MJPEG part has the wrong size')
                numbers.append(int(m.group(2)))
                buf = buf[m.end() + int(m.group(1)):]
                # The boundary that ends this part follows the image at once.
                while len(buf) < 18:
                    buf += sock.recv(65536)
                check(buf.startswith(b'\r\n--cablefilmframe\r\n'), 'no boundary right after a part')
        sock.close()
        check(len(numbers) == 2, 'MJPEG gave no two parts')
        check(numbers[1] > numbers[0], f'MJPEG frame numbers {numbers} do not increase')
        # WebSocket: binary frames with the header, state messages, and a control reply.
        ws = websocket.create_connection(srv.base.replace('http', 'ws') + '/ws', timeout=20)
        got_frames, got_state = [], None
        deadline = time.time() + 20
        while (len(got_frames) < 3 or not got_state) and time.time() < deadline:
            op, data = ws.recv_data()
            if op == websocket.ABNF.OPCODE_BINARY:
                number, t, seq = struct.unpack('<QdQ', data[:24])
                check(jpeg_size(data[24:]) == (WIDTH, HEIGHT), 'a WebSocket frame has the wrong size')
                got_frames.append((number, t))
            elif op == websocket.ABNF.OPCODE_TEXT:
                msg = json.loads(data)
                if msg.get('type') == 'state':
                    got_state = msg
        check(len(got_frames) >= 3 and got_state, 'the WebSocket gave no 3 frames and a state')
        check(all(a[0] < b[0] and a[1] <= b[1] for a, b in zip(got_frames, got_frames[1:])),
              f'WebSocket frames out of order: {got_frames}')
        ws.send(json.dumps({'speed': 99}))
        deadline = time.time() + 20
        while time.time() < deadline:
            op, data = ws.recv_data()
            if op == websocket.ABNF.OPCODE_TEXT and json.loads(data).get('type') == 'reply':
                reply = json.loads(data)
                check(reply['ok'] is False and reply['error'].startswith('speed:'),
                      f'a bad WebSocket control was answered {reply}')
                break
        else:
            raise Failure('no reply to a WebSocket control')
        ws.close()

    def pause_and_step():
        code, st = srv.control({'pause': True})
        check(code == 200 and st['paused'] is True, f'pause answered {code} {st}')
        st = srv.wait(lambda s: s['seq_applied'] >= st['seq'], 'the pause to be applied')
        t0 = st['t']
        time.sleep(1.0)
        check(srv.state()['t'] == t0, 'paused, t still moves')
        code, st = srv.control({'step': True})
        st = srv.wait(lambda s: s['t'] > t0, 'a step')
        check(abs(st['t'] - t0 - 1 / 30) < 1e-6, f'a step advanced {st["t"] - t0} s, not one frame')
        check(st['paused'], 'a step resumed the run')
        srv.control({'pause': False})

    def bad_controls():
        for body, field in ((b'{"speed": 50}', 'speed:'), (b'{"sped": 1}', 'unknown field'),
                            (b'not json', 'control: malformed JSON'),
                            (b'{"current": "fast"}', 'current:'), (b'{"pause": 1}', 'pause:'),
                            (b'{"period": -3}', 'period:'), (b'{"colormap": "jet"}', 'colormap:'),
                            (b'{"current_heading": 400}',
                             'current_heading: expected a number in [-360, 360] degrees'),
                            (b'{"current_heading": "east"}', 'current_heading:'),
                            (b'{"wave_heading": 30}', 'wave_heading: the scene has no [waves]')):
            before = srv.state()
            code, reply = srv.control(body)
            check(code == 400 and reply['error'].startswith(field),
                  f'{body!r} answered {code} {reply}')
            after = srv.state()
            for key in ('speed', 'current', 'period', 'paused', 'colormap', 'amplitude_scale',
                        'current_heading', 'wave_heading'):
                check(before[key] == after[key], f'a refused control changed {key}')
        code, reply = srv.control(b'{' + b' ' * 5000 + b'}')
        check(code in (400, 413), f'a 5 kB control answered {code}')
        try:
            srv.get('/control')
            raise Failure('GET /control answered 200')
        except urllib.error.HTTPError as e:
            check(e.code == 405, f'GET /control answered {e.code}')
        check(srv.get('/state')[0] == 200, 'the server stopped serving after bad controls')

    def hostile_input():
        # Seeded random bodies (fields, atoms, binary, deep nesting) and raw garbage on the
        # socket: every control is answered 200 or 400 and the server keeps serving. Deep
        # nesting once overflowed a server thread's stack.
        import random
        rng = random.Random(7)
        atoms = ['true', 'false', 'null', '1', '-1', '1e999', '0.5', '"x"', '"viridis"', '[]',
                 '{}', '[0,1]', '"\\u0000"', '1e-400', 'NaN', 'Infinity']
        keys = ['pause', 'speed', 'amplitude_scale', 'period', 'current', 'colormap',
                'lock_range', 'tension_range', 'x', '']
        for i in range(300):
            r = rng.random()
            if r < 0.5:
                body = ('{' + ','.join(f'"{rng.choice(keys)}":{rng.choice(atoms)}'
                                       for _ in range(rng.randint(0, 4))) + '}').encode()
            elif r < 0.75:
                body = bytes(rng.randint(0, 255) for _ in range(rng.randint(0, 200)))
            else:
                depth = rng.randint(1, 2000)
                body = b'[' * depth + b']' * depth
            code, reply = srv.control(body)
            check(code in (200, 400, 413) and ('error' in reply) == (code != 200),
                  f'{body[:60]!r} answered {code} {reply}')
            if i % 50 == 0:
                s = socket.create_connection(('127.0.0.1', srv.port))
                s.sendall(bytes(rng.randint(0, 255) for _ in range(rng.randint(1, 5000))))
                s.close()
        srv.control({'pause': False, 'speed': 1, 'amplitude_scale': 1, 'period': 10, 'current': 0})
        check(srv.get('/state')[0] == 200, 'the server stopped serving after hostile input')

    def stalled_viewer():
        # A viewer that asks for the stream and never reads: the simulation keeps real time.
        sock = socket.create_connection(('127.0.0.1', srv.port))
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        sock.sendall(b'GET /stream.mjpg HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n')
        s0, w0 = srv.state()['t'], time.time()
        time.sleep(3.0)
        st = srv.state()
        rate = (st['t'] - s0) / (time.time() - w0)
        sock.close()
        check(0.9 < rate < 1.1, f'with a stalled viewer t advanced at {rate:.3f} x real time')

    def record():
        code, st = srv.control({'record': True})
        check(code == 200, f'record answered {code}')
        st = srv.wait(lambda s: s['recording'], 'the recording to start')
        f0 = st['frame']
        time.sleep(2.0)
        code, st = srv.control({'record': False})
        st = srv.wait(lambda s: not s['recording'] and s['recordings'], 'the recording to close')
        rec = st['recordings'][-1]
        check(re.fullmatch(r'live-\d{8}-\d{6}\.mp4', rec['name']), f'recording name {rec["name"]}')
        path = os.path.join(srv.out_dir, rec['name'])
        check(os.path.exists(path), f'{path} does not exist')
        status, headers, body = srv.get(rec['url'])
        check(headers['Content-Type'] == 'video/mp4', 'the recording is not served as video/mp4')
        frames, w, h = mp4_video(body)
        check((w, h) == (WIDTH, HEIGHT), f'the film is {w}x{h}')
        # About 2 s at 30 frames/s; every frame drawn while recording, each once.
        check(frames == rec['frames'] and 45 <= frames <= 120,
              f'the film has {frames} frames, the server says {rec["frames"]}')
        try:
            srv.get('/recordings/../../etc/passwd')
            raise Failure('a path outside the recordings was served')
        except urllib.error.HTTPError as e:
            check(e.code == 404, f'a bad recording path answered {e.code}')

    def amplitude_and_period():
        code, st = srv.control({'amplitude_scale': 1.5, 'period': 8})
        check(code == 200 and st['amplitude_scale'] == 1.5 and st['period'] == 8,
              f'amplitude and period answered {code} {st}')
        check(srv.state()['amplitude_scale'] == 1.5, '/state does not show the amplitude')

    def timeseries():
        _, headers, body = srv.get('/timeseries.csv')
        lines = body.decode().splitlines()
        check(lines[0] == ('t,x_end,y_end,z_end,tension_start,tension_end,tension_max,link_max'
              ',fx_start,fy_start,fz_start,fx_end,fy_end,fz_end,angle_start,angle_end'),
              f'CSV header {lines[0]}')
        ts = [float(line.split(',')[0]) for line in lines[1:] if line]
        check(len(ts) > 100 and all(a < b for a, b in zip(ts, ts[1:])),
              f'{len(ts)} rows, times not increasing')
        check(abs(ts[-1] - srv.state()['t']) < 1.0, 'the CSV lags the state')

    def restart():
        code, st = srv.control({'restart': True})
        st = srv.wait(lambda s: s['seq_applied'] >= st['seq'], 'the restart')
        check(st['t'] < 1.0 and st['amplitude_scale'] == 1.0 and st['period'] == 10,
              f'after a restart: {st}')

    def sigterm_closes_recording():
        srv.control({'record': True})
        srv.wait(lambda s: s['recording'], 'a recording')
        time.sleep(1.0)
        code = srv.stop()
        check(code == 0, f'SIGTERM exit status {code}')
        films = sorted(f for f in os.listdir(out_dir) if f.startswith('live-') and f.endswith('.mp4'))
        check(len(films) >= 2, f'the recording in progress was not closed: {films}')
        with open(os.path.join(out_dir, films[-1]), 'rb') as f:
            frames, w, h = mp4_video(f.read())
        check(frames >= 15 and (w, h) == (WIDTH, HEIGHT), f'the last film: {frames} frames {w}x{h}')
        leftovers = [f for f in os.listdir(out_dir) if 'tmp' in f or 'partial' in f]
        check(not leftovers, f'temporary files left behind: {leftovers}')

    try:
        for name, fn in (('page and assets, served from the binary', page),
                         ('t advances in real time; /state fields', real_time),
                         ('frames: JPEG, PNG, MJPEG, WebSocket at the asked size', frames),
                         ('pause stops t; step advances one frame', pause_and_step),
                         ('bad controls answer 400 naming the field, change nothing', bad_controls),
                         ('hostile input: every control answered, the server keeps serving', hostile_input),
                         ('a stalled viewer slows nothing', stalled_viewer),
                         ('amplitude and period in /state', amplitude_and_period),
                         ('recording: a playable MP4 of the frames shown', record),
                         ('/timeseries.csv', timeseries),
                         ('restart', restart),
                         ('SIGTERM exits 0 and closes the recording', sigterm_closes_recording)):
            step(name, fn)
    finally:
        if srv.proc.poll() is None:
            srv.proc.kill()

    # The current: on the scene with its fairlead held still the tensions stay at the
    # equilibrium's until the current changes them.
    with open(args.scene) as f:
        text = f.read()
    # The [ends.end] table with its fairlead held still at the same rest position.
    fixed = re.sub(r'^\[ends\.end\].*?(?=^\[)', '[ends.end]\nposition = [80.0, 30.48]\nmotion = "fixed"\n\n',
                   text, flags=re.DOTALL | re.MULTILINE)
    scene2 = os.path.join(out_dir, 'still_fairlead.toml')
    with open(scene2, 'w') as f:
        f.write(fixed)
    srv2 = Server(args.cablefilm, scene2, out_dir)

    def current():
        st0 = srv2.wait(lambda s: s['t'] > 0.5, 'the run to start')
        code, st = srv2.control({'current': 1.0})
        check(code == 200 and st['current'] == 1.0, f'current answered {code} {st}')
        check(srv2.state()['current'] == 1.0, '/state does not show the current')
        st1 = srv2.wait(lambda s: s['t'] > st0['t'] + 8, 'the current to ramp in')
        change = abs(st1['tension']['end'] - st0['tension']['end'])
        # The still line sits at its equilibrium to within newtons; 1 m/s of current on 91 m of
        # line (drag ~1.5 kN) moves the fairlead tension by hundreds of newtons.
        check(change > 50, f'the fairlead tension changed by {change:.2f} N only')

    def current_heading():
        # The current turned across the line (along +z): over its 5 s ramp, the short way
        # round; the fairlead tension changes as the line is pushed out of its plane.
        st = srv2.state()
        check(st['current_heading'] == 0 and st['limits']['current_heading'] == [-360, 360],
              f'the scene\'s heading and its limits: {st["current_heading"]}, {st["limits"]}')
        code, st = srv2.control({'current_heading': -270})  # the same as 90
        check(code == 200 and st['current_heading'] == -270, f'current_heading answered {code} {st}')
        st0 = srv2.wait(lambda s: s['seq_applied'] >= st['seq'], 'the heading to be applied')
        st1 = srv2.wait(lambda s: s['t'] > st0['t'] + 6, 'the heading to ramp')
        check(abs(st1['current_heading_now'] - 90) < 1e-9,
              f'the current turned to {st1["current_heading_now"]} degrees, not 90 (the short '
              f'way from 0)')
        change = abs(st1['tension']['end'] - st0['tension']['end'])
        check(change > 10, f'the fairlead tension changed by {change:.2f} N only')
        code, reply = srv2.control({'current_heading': 361})
        check(code == 400 and reply['error'].startswith('current_heading:'),
              f'361 degrees answered {code} {reply}')
        check(srv2.state()['current_heading'] == -270, 'a refused heading changed the state')
        check(srv2.stop() == 0, 'SIGTERM exit status')

    try:
        step('a current change shows in /state and changes the tensions', current)
        step('the current heading turns the current and shows in /state', current_heading)
    finally:
        if srv2.proc.poll() is None:
            srv2.proc.kill()

    # The waves' heading, on a scene with waves (scenes/grounded_mooring.toml), at 5x real time.
    srv3 = Server(args.cablefilm, os.path.join(os.path.dirname(os.path.abspath(args.scene)),
                                               'grounded_mooring.toml'), out_dir)

    def wave_heading():
        st = srv3.state()
        check(st['has_waves'] and st['wave_heading'] == 0 and
              st['limits']['wave_heading'] == [-360, 360], f'the scene\'s waves: {st}')
        code, st = srv3.control({'wave_heading': 30, 'speed': 5})
        check(code == 200 and st['wave_heading'] == 30, f'wave_heading answered {code} {st}')
        st0 = srv3.wait(lambda s: s['seq_applied'] >= st['seq'], 'the heading to be applied')
        # One wave period (10 s) of ramp, at 5x.
        st1 = srv3.wait(lambda s: s['t'] > st0['t'] + 10.5, 'the waves to turn', timeout=60)
        check(abs(st1['wave_heading_now'] - 30) < 1e-9,
              f'the waves turned to {st1["wave_heading_now"]} degrees, not 30')
        code, reply = srv3.control({'wave_heading': -361})
        check(code == 400 and reply['error'].startswith('wave_heading: expected a number in '
                                                        '[-360, 360]'),
              f'-361 degrees answered {code} {reply}')
        check(srv3.stop() == 0, 'SIGTERM exit status')

    try:
        step('the wave heading turns the waves and shows in /state', wave_heading)
    finally:
        if srv3.proc.poll() is None:
            srv3.proc.kill()

    # A system of lines (scenes/spread_mooring.toml: four lines, three anchors, a clump weight,
    # three fairleads on a ship in surge and heave), at 5x real time.
    srv4 = Server(args.cablefilm, os.path.join(os.path.dirname(os.path.abspath(args.scene)),
                                               'spread_mooring.toml'), out_dir)

    def system():
        st = srv4.state()
        names = [l['name'] for l in st.get('lines', [])]
        check(names == ['leg1_lower', 'leg1_upper', 'leg2', 'leg3'],
              f'the system\'s lines: {names}')
        # Its controls are what it has: the fairleads' orbit (a driven end: amplitude and
        # period), the ship that carries them (offsets); no free body, no waves.
        check(st['has_offset'] and not st['has_force'] and st['has_period']
              and st['period'] == 12 and not st['has_waves'] and not st['current_from_table']
              and st['limits']['offset'] == [-25, 25],
              f'a system\'s controls: {st}')
        check(all(l['max'] > 0 for l in st['lines']), 'a line with no tension')
        check(st['tension']['max'] == max(l['max'] for l in st['lines']),
              'the maximum is not the largest of the lines\'')
        # Controls of what it does not have, and hostile ones: 400 naming the field.
        for body, start in (({'wave_height': 2}, 'wave_height: the scene has no [waves]'),
                            ({'amplitude_scale': 99}, 'amplitude_scale: expected a number'),
                            ({'offset_x': 26}, 'offset_x: expected a number in [-25, 25]'),
                            ({'offset_z': [1, 2]}, 'offset_z: expected a number'),
                            (b'{"offset_x": 1e999}', 'control: malformed JSON'),  # overflows the parser
                            (b'{"offset_z": -1e308}', 'offset_z: expected a number'),
                            ({'offset_x': None}, 'offset_x: expected a number'),
                            ({'force_x': 1e5}, 'force_x: the scene has no free body')):
            code, reply = srv4.control(body)
            check(code == 400 and reply.get('error', '').startswith(start),
                  f'{body!r} answered {code} {reply}')
        code, st = srv4.control({'offset_x': 5, 'offset_z': -2, 'current_heading': 90, 'speed': 5})
        check(code == 200 and st['offset_x'] == 5 and st['offset_z'] == -2,
              f'the offset answered {code} {st}')
        st0 = srv4.wait(lambda s: s['seq_applied'] >= st['seq'], 'the offset to be applied')
        # The ramps: 5 s (15/8 x 5 m at 2 m/s is less), the current's 5 s; at 5x.
        st1 = srv4.wait(lambda s: s['t'] > st0['t'] + 5.5, 'the vessel to move', timeout=60)
        check(st1['offset_x_now'] == 5 and st1['offset_z_now'] == -2,
              f'the vessel is offset by {st1["offset_x_now"]}, {st1["offset_z_now"]} m')
        check(abs(st1['current_heading_now'] - 90) < 1e-9,
              f'the current turned to {st1["current_heading_now"]} degrees, not 90')
        _, headers, png = srv4.get('/snapshot.png')
        check(png[:8] == b'\x89PNG\r\n\x1a\n' and headers['Content-Type'] == 'image/png',
              'the snapshot is not a PNG')
        width, height = struct.unpack('>II', png[16:24])
        check((width, height) == (WIDTH, HEIGHT), f'the snapshot is {width}x{height}')
        with open(os.path.join(out_dir, 'system_snapshot.png'), 'wb') as f:
            f.write(png)
        _, _, jpeg = srv4.get('/frame.jpg')
        check(jpeg_size(jpeg) == (WIDTH, HEIGHT), 'the system\'s frame is not a JPEG of the size')
        _, _, csv = srv4.get('/timeseries.csv')
        lines = csv.decode().splitlines()
        header = lines[0].split(',')
        check(header[:8] == ['t', 'current', 'current_heading', 'offset_x', 'offset_z',
                             'force_x', 'force_z', 'tension_max_leg1_lower']
              and len(header) == 7 + 2 * 4 + 6 * 7,
              f'the system\'s time series header: {lines[0][:200]}')
        last = lines[-1].split(',')
        check(len(last) == len(header) and float(last[3]) == 5.0,
              f'the last row: {lines[-1][:200]}')
        # Pause, step one frame, restart (the scene's vessel and current again).
        code, st = srv4.control({'pause': True})
        stp = srv4.wait(lambda s: s['paused'] and s['seq_applied'] >= st['seq'], 'the pause')
        code, st = srv4.control({'step': True})
        st2 = srv4.wait(lambda s: s['t'] > stp['t'], 'a step')
        check(abs(st2['t'] - stp['t'] - 5 / 30) < 1e-6, f'a step advanced {st2["t"] - stp["t"]} s')
        code, st = srv4.control({'restart': True})
        check(code == 200 and st['offset_x'] == 0 and st['offset_z'] == 0, f'restart: {st}')
        srv4.wait(lambda s: s['seq_applied'] >= st['seq'] and s['t'] == 0, 'the restart')
        check(srv4.stop() == 0, 'SIGTERM exit status')

    try:
        step('a system: its lines, its vessel offset, its controls, snapshot and time series',
             system)
    finally:
        if srv4.proc.poll() is None:
            srv4.proc.kill()

    # A current over time (environment.current_file): the table's, which the page shows and
    # does not offer as a control.
    scenes = os.path.dirname(os.path.abspath(args.scene))
    with open(os.path.join(scenes, 'spread_mooring.toml'), encoding='utf-8') as f:
        text = f.read()
    text = re.sub(r'^current_heading = .*$', '', text, flags=re.M)
    text = re.sub(r'^(current = \[\[.*)$', r'\1\ncurrent_file = "current.csv"', text, count=1,
                  flags=re.M)
    with open(os.path.join(out_dir, 'current.csv'), 'w', encoding='utf-8') as f:
        f.write('t,scale,heading\n0,1,0\n100,0.5,90\n')
    with open(os.path.join(out_dir, 'current_table.toml'), 'w', encoding='utf-8') as f:
        f.write(text)
    srv5 = Server(args.cablefilm, os.path.join(out_dir, 'current_table.toml'), out_dir)

    def current_table():
        st = srv5.state()
        # The table turns it from 0 to 90 degrees over 100 s: 0.9 t (within a frame's 0.03).
        check(st['current_from_table'] and
              abs(st['current_heading_now'] - 0.9 * st['t']) < 0.1,
              f'a current table: heading {st["current_heading_now"]} at t = {st["t"]} s')
        code, reply = srv5.control({'current': 1})
        check(code == 400 and 'current' in reply.get('error', ''),
              f'a current control over a table answered {code} {reply}')
        check(srv5.stop() == 0, 'SIGTERM exit status')

    try:
        step('a current over time is the table\'s, no control', current_table)
    finally:
        if srv5.proc.poll() is None:
            srv5.proc.kill()

    failed = sum(1 for _, e in results if e)
    print(f'{len(results) - failed} passed, {failed} failed')
    return 1 if failed else 0


if __name__ == '__main__':
    p = argparse.ArgumentParser()
    p.add_argument('--cablefilm', required=True)
    p.add_argument('--scene', required=True)
    p.add_argument('--out-dir')
    sys.exit(run(p.parse_args()))
