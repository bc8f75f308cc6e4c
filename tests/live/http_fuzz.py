#!/usr/bin/python3
"""A seeded fuzzer of the live server's HTTP and WebSocket endpoints, run for a bounded time.

    /usr/bin/python3 tests/live/http_fuzz.py --cablefilm ./build/cablefilm \\
        --scene scenes/polachek1963.toml --out-dir /tmp/live-fuzz [--seconds 25] [--seed 22]

First replays every input of tests/live/fuzz_corpus/ (the seeds, and every input that ever
broke the server, kept as regressions), then sends inputs made from them and from scratch by a
random.Random(seed): random methods, paths, Host/Origin/Cookie headers, huge and many headers,
wrong Content-Length and broken chunked bodies, byte flips and cuts (*.http, sent raw on a new
connection); and after a real handshake, broken WebSocket frames: reserved bits, unmasked,
lengths announced beyond what is sent or up to 2^63 (then fed filler past the memory bound
while the server takes it), control frames too long or fragmented,
continuations out of place, oversized messages, controls of random and invalid JSON (*.ws).

After every input the server must be up; every 25 inputs and at the end it must answer
GET /state with its JSON, accept a WebSocket and deliver a frame, and its resident memory
(/proc/PID/status VmRSS) must stay under its size after start-up plus --rss-mib. An input that
breaks it is written to OUT-DIR/failures/ (copy it into tests/live/fuzz_corpus/ to keep it).
The inputs depend on the seed only; what the server answers may depend on timing.
Prints `N passed, M failed` (inputs answered, inputs that broke it); exits 1 on any failure.
"""
import argparse
import base64
import hashlib
import json
import os
import random
import re
import signal
import socket
import struct
import subprocess
import sys
import time

CORPUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'fuzz_corpus')
READY = re.compile(r'live view at http://127\.0\.0\.1:(\d+)/\s*$')

PATHS = ['/', '/index.html', '/app.js', '/style.css', '/state', '/frame.jpg', '/snapshot.png',
         '/timeseries.csv', '/stream.mjpg', '/control', '/ws', '/recordings/', '/recordings/x.mp4',
         '/recordings/../../etc/passwd', '/%2e%2e/%2e%2e/etc/passwd', '/state?token=x', '//state',
         '/state#x', '/favicon.ico', '*', 'http://127.0.0.1/state', '/' + 'a' * 5000]
METHODS = ['GET', 'POST', 'HEAD', 'OPTIONS', 'PUT', 'DELETE', 'PATCH', 'TRACE', 'CONNECT',
           'PROPFIND', 'get', 'G\x00T', '', 'X' * 300]
CONTROL_KEYS = ['pause', 'step', 'restart', 'speed', 'amplitude_scale', 'period', 'current',
                'wave_height', 'wave_period', 'colormap', 'lock_range', 'reset_range',
                'tension_range', 'record', '', 'x', '\u0000', 'pause\u0000']
ATOMS = ['true', 'false', 'null', '0', '1', '-1', '1e308', '1e999', '-0', '0.5', '"x"',
         '"viridis"', '[]', '{}', '[0,1]', '[1,0]', '[0,1e9]', '"\\u0000"', 'NaN', 'Infinity',
         '"\\ud800"', '1' * 400]


class Broke(Exception):
    pass


class Server:
    def __init__(self, binary, scene, out_dir):
        self.log = open(os.path.join(out_dir, 'server.log'), 'w')
        # Under AddressSanitizer, freed memory waits in a quarantine of up to 256 MiB before it is
        # reused, which would read as growth of the server's memory: the bound is about what the
        # server keeps, so the quarantine is held well below it (16 MiB still catches
        # use-after-free of recent blocks). Without ASan the option is ignored.
        env = dict(os.environ)
        env['ASAN_OPTIONS'] = ':'.join(filter(None, [env.get('ASAN_OPTIONS', ''),
                                                     'quarantine_size_mb=16']))
        self.proc = subprocess.Popen(
            [binary, 'live', scene, '--port', '0', '--size', '320x180', '--out',
             os.path.join(out_dir, 'films')], stdout=subprocess.PIPE, stderr=self.log, text=True,
            env=env)
        deadline = time.time() + 120
        self.port = None
        while time.time() < deadline and self.port is None:
            line = self.proc.stdout.readline()
            if not line:
                break
            m = READY.match(line)
            self.port = int(m.group(1)) if m else None
        if self.port is None:
            self.proc.kill()
            raise SystemExit('the server did not start; see ' + self.log.name)

    def rss_kib(self):
        with open(f'/proc/{self.proc.pid}/status') as f:
            for line in f:
                if line.startswith('VmRSS:'):
                    return int(line.split()[1])
        return 0

    def alive(self):
        return self.proc.poll() is None

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                return self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                return -9
        return self.proc.returncode


def connect(port, timeout=20):  # generous: a loaded machine may be slow to answer
    s = socket.create_connection(('127.0.0.1', port), timeout=timeout)
    s.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack('ii', 1, 0))  # no TIME_WAIT pile
    return s


def drain(sock, limit=1 << 20, seconds=1.0):
    """Reads what the server answers, up to `limit` bytes or `seconds`; the bytes."""
    sock.settimeout(0.2)
    data, deadline = b'', time.time() + seconds
    while len(data) < limit and time.time() < deadline:
        try:
            chunk = sock.recv(65536)
        except socket.timeout:
            continue
        except OSError:
            break
        if not chunk:
            break
        data += chunk
    return data


def send_http(port, raw):
    sock = connect(port)
    try:
        sock.sendall(raw)
    except OSError:
        pass  # the server may hang up on a bad request before reading all of it
    data = drain(sock)
    sock.close()
    return data


def handshake(port, key=None):
    """A WebSocket upgraded: (socket, the bytes after the answer's headers, which may already
    hold the server's first frame or part of it)."""
    sock = connect(port)
    key = key or base64.b64encode(b'cablefilm-fuzzer').decode()
    sock.sendall((f'GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\n'
                  f'Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n'
                  f'Sec-WebSocket-Version: 13\r\nOrigin: http://127.0.0.1:{port}\r\n\r\n').encode())
    data = b''
    sock.settimeout(30)
    while b'\r\n\r\n' not in data:
        chunk = sock.recv(65536)
        if not chunk:
            raise Broke('the WebSocket handshake got no answer: %r' % data[:100])
        data += chunk
    status = data.split(b'\r\n', 1)[0]
    if b' 101 ' not in status + b' ':
        raise Broke('the WebSocket handshake answered %r' % status)
    return sock, data.partition(b'\r\n\r\n')[2]


def announces_more(raw):
    """Whether the last frame of `raw` announces more payload than `raw` holds."""
    i = 0
    while i + 2 <= len(raw):
        n, off = raw[i + 1] & 0x7f, 2
        if n == 126:
            if i + 4 > len(raw):
                return False
            n, off = struct.unpack('>H', raw[i + 2:i + 4])[0], 4
        elif n == 127:
            if i + 10 > len(raw):
                return False
            n, off = struct.unpack('>Q', raw[i + 2:i + 10])[0], 10
        off += 4 if raw[i + 1] & 0x80 else 0
        if i + off + n > len(raw):
            return n > 125
        i += off + n
    return False


def send_ws(port, raw, srv=None, flood_limit=0):
    """Sends `raw` after a handshake. A frame announcing more than is sent is then fed filler,
    up to `flood_limit` bytes, while the server takes it: the server must refuse it by its
    header, so its memory must not grow with what is sent (checked before hanging up)."""
    sock, _ = handshake(port)
    try:
        sock.sendall(raw)
        if flood_limit and announces_more(raw):
            filler, sent = b'f' * (1 << 20), 0
            sock.settimeout(2)
            while sent < flood_limit:
                sock.sendall(filler)
                sent += len(filler)
    except OSError:
        pass  # closed on a refused header: what is wanted
    if srv is not None and flood_limit and srv.rss_kib() > srv.rss_limit_kib:
        sock.close()
        raise Broke(f'the server holds {srv.rss_kib()} KiB with a frame being fed (limit {srv.rss_limit_kib} KiB)')
    data = drain(sock, seconds=0.3)
    sock.close()
    return data


# ---- making inputs ------------------------------------------------------------------------------
def frame(rng, opcode, payload, fin=True, mask=True, rsv=0, announce=None):
    n = len(payload) if announce is None else announce
    head = bytes([(0x80 if fin else 0) | (rsv << 4) | opcode])
    m = 0x80 if mask else 0
    if n < 126:
        head += bytes([m | n])
    elif n < 65536:
        head += bytes([m | 126]) + struct.pack('>H', n)
    else:
        head += bytes([m | 127]) + struct.pack('>Q', n)
    if not mask:
        return head + payload
    key = bytes(rng.randrange(256) for _ in range(4))
    return head + key + bytes(b ^ key[i % 4] for i, b in enumerate(payload))


def control_json(rng):
    r = rng.random()
    if r < 0.5:
        return ('{' + ','.join(f'"{rng.choice(CONTROL_KEYS)}":{rng.choice(ATOMS)}'
                               for _ in range(rng.randint(0, 4))) + '}').encode('utf-8', 'surrogatepass')
    if r < 0.7:
        depth = rng.randint(1, 3000)
        return b'[' * depth + b']' * depth
    if r < 0.85:
        return bytes(rng.randrange(256) for _ in range(rng.randint(0, 300)))
    return json.dumps({'speed': rng.uniform(-20, 20), 'current': rng.uniform(-5, 5),
                       'record': rng.random() < 0.1}).encode()


def make_ws(rng):
    frames = b''
    for _ in range(rng.randint(1, 6)):
        r = rng.random()
        if r < 0.35:
            frames += frame(rng, 1, control_json(rng))
        elif r < 0.45:  # a frame announcing more than it sends, up to 2^63
            frames += frame(rng, rng.choice([0, 1, 2]), b'x' * rng.randint(0, 64),
                            fin=rng.random() < 0.5, announce=rng.choice([126, 4097, 65536, 1 << 30, (1 << 63) - 1, 1 << 63]))
        elif r < 0.55:  # a message in fragments, past the limit or not
            size = rng.choice([100, 4096, 4097, 9000])
            body = b' ' * size
            cut = sorted(rng.randint(0, size) for _ in range(rng.randint(1, 4)))
            parts = [body[a:b] for a, b in zip([0] + cut, cut + [size])]
            for i, p in enumerate(parts):
                frames += frame(rng, 1 if i == 0 else 0, p, fin=i == len(parts) - 1)
        elif r < 0.65:  # control frames, good and bad
            op = rng.choice([8, 9, 10, 11, 15])
            frames += frame(rng, op, bytes(rng.randrange(256) for _ in range(rng.choice([0, 1, 2, 125, 126, 200]))),
                            fin=rng.random() < 0.8)
        elif r < 0.75:  # reserved bits, no mask, stray continuation, unknown opcodes
            frames += frame(rng, rng.choice([0, 3, 7]), b'{}', mask=rng.random() < 0.5, rsv=rng.randrange(8))
        elif r < 0.85:
            frames += frame(rng, 2, bytes(rng.randrange(256) for _ in range(rng.randint(0, 500))))
        else:
            frames += bytes(rng.randrange(256) for _ in range(rng.randint(1, 64)))
    return frames


def make_http(rng, port):
    method = rng.choice(METHODS)
    path = rng.choice(PATHS)
    if rng.random() < 0.2:
        path += '?' + '&'.join(f'{rng.choice(["token", "n", "x", ""])}={rng.randint(0, 9) * "%00"}'
                               for _ in range(rng.randint(1, 4)))
    version = rng.choice(['HTTP/1.1'] * 6 + ['HTTP/1.0', 'HTTP/2.0', 'HTTP/9', 'HTTPS/1.1', ''])
    headers = []
    r = rng.random()
    if r < 0.6:
        headers.append(('Host', f'127.0.0.1:{port}'))
    elif r < 0.8:
        headers.append(('Host', rng.choice(['evil.example', 'localhost', '[::1]:1', '[', ':', '127.0.0.1:99999999',
                                            'x' * 3000, '127.0.0.1\x00evil'])))
    if rng.random() < 0.3:
        headers.append(('Origin', rng.choice([f'http://127.0.0.1:{port}', 'http://evil.example', 'null', '', 'x' * 500])))
    if rng.random() < 0.15:
        headers.append(('Sec-Fetch-Site', rng.choice(['cross-site', 'same-site', 'same-origin', 'none', 'x'])))
    if rng.random() < 0.15:
        headers.append(('Cookie', rng.choice(['cablefilm_token=' + 'a' * 32, 'cablefilm_token=', ';;;=', 'x=' * 2000])))
    if rng.random() < 0.2:
        headers.append(('Upgrade', 'websocket'))
        headers.append(('Connection', rng.choice(['Upgrade', 'keep-alive, Upgrade', 'close'])))
        if rng.random() < 0.7:
            headers.append(('Sec-WebSocket-Key', rng.choice(['dGhlIHNhbXBsZSBub25jZQ==', 'short', '=' * 24, ''])))
        if rng.random() < 0.7:
            headers.append(('Sec-WebSocket-Version', rng.choice(['13', '8', 'x', ''])))
    body = b''
    r = rng.random()
    if r < 0.4:
        body = control_json(rng)
        headers.append(('Content-Length', str(rng.choice([len(body)] * 4 + [0, len(body) + 10, -1, 10 ** 20, 'x']))))
    elif r < 0.5:
        body = control_json(rng)
        headers.append(('Transfer-Encoding', 'chunked'))
        body = (b'%x\r\n' % len(body) + body + b'\r\n0\r\n\r\n') if rng.random() < 0.5 else (
            rng.choice([b'zz\r\n', b'ffffffffffffffff\r\nabc', b'5\r\nab', b'-1\r\n\r\n']))
    elif r < 0.55:
        body = b'{' + b' ' * rng.choice([4096, 5000, 70000]) + b'}'
        headers.append(('Content-Length', str(len(body))))
    if rng.random() < 0.1:  # a huge header, or very many
        if rng.random() < 0.5:
            headers.append(('X-Big', 'b' * rng.choice([8000, 17000, 70000])))
        else:
            headers += [(f'X-{i}', 'v') for i in range(rng.choice([60, 200, 2000]))]
    text = f'{method} {path} {version}\r\n' + ''.join(f'{k}: {v}\r\n' for k, v in headers) + '\r\n'
    raw = text.encode('utf-8', 'surrogatepass') + body
    return mutate(rng, raw) if rng.random() < 0.25 else raw


def mutate(rng, raw):
    raw = bytearray(raw)
    for _ in range(rng.randint(1, 8)):
        if not raw:
            break
        r, i = rng.random(), rng.randrange(len(raw))
        if r < 0.4:
            raw[i] = rng.randrange(256)
        elif r < 0.6:
            del raw[i:i + rng.randint(1, 16)]
        elif r < 0.8:
            raw[i:i] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 16)))
        else:
            raw = raw[:i]
    return bytes(raw)


# ---- the run ------------------------------------------------------------------------------------
def healthy(srv, rss_limit_kib):
    """Raises Broke unless the server answers /state, streams a frame, and stays within memory."""
    if not srv.alive():
        raise Broke(f'the server exited with status {srv.proc.returncode}')
    data = send_http(srv.port, f'GET /state HTTP/1.1\r\nHost: 127.0.0.1:{srv.port}\r\n\r\n'.encode())
    head, _, body = data.partition(b'\r\n\r\n')
    if not head.startswith(b'HTTP/1.1 200'):
        raise Broke('GET /state answered %r' % head[:80])
    try:
        json.loads(body)
    except ValueError:
        raise Broke('GET /state gave no JSON: %r' % body[:80])
    # The server's frames in order from the first byte after the handshake (which may have come
    # with it), state messages skipped whole, to its first binary frame. 30 s: a loaded machine.
    sock, got = handshake(srv.port)
    deadline = time.time() + 30
    binary = False
    while not binary:
        while len(got) >= 2:
            if got[0] & 0xf0 != 0x80 or got[0] & 0x0f not in (1, 2, 8, 9, 10) or got[1] & 0x80:
                sock.close()
                raise Broke('the WebSocket sent a frame header it should not: %r' % got[:12])
            n, off = got[1] & 0x7f, 2
            if n == 126:
                if len(got) < 4:
                    break
                n, off = struct.unpack('>H', got[2:4])[0], 4
            elif n == 127:
                if len(got) < 10:
                    break
                n, off = struct.unpack('>Q', got[2:10])[0], 10
            if got[0] == 0x82:
                binary = True
                break
            if len(got) < off + n:
                break
            got = got[off + n:]
        if binary or time.time() >= deadline:
            break
        sock.settimeout(max(0.1, deadline - time.time()))
        try:
            chunk = sock.recv(65536)
        except socket.timeout:
            break
        if not chunk:
            break
        got += chunk
    sock.close()
    if not binary:
        raise Broke('a WebSocket viewer got no frame within 30 s')
    rss = srv.rss_kib()
    if rss > rss_limit_kib:
        raise Broke(f'the server holds {rss} KiB (limit {rss_limit_kib} KiB)')
    return rss


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('--cablefilm', required=True)
    p.add_argument('--scene', required=True)
    p.add_argument('--out-dir', required=True)
    p.add_argument('--seconds', type=float, default=25, help='time for the random inputs (default 25)')
    p.add_argument('--seed', type=int, default=22)
    p.add_argument('--rss-mib', type=float, default=96,
                   help='growth of resident memory allowed over its size after start-up (default 96)')
    a = p.parse_args()
    os.makedirs(a.out_dir, exist_ok=True)
    failures_dir = os.path.join(a.out_dir, 'failures')
    srv = Server(a.cablefilm, a.scene, a.out_dir)
    passed = failed = 0
    rss0 = srv.rss_kib()
    limit = rss0 + int(a.rss_mib * 1024)
    srv.rss_limit_kib = limit
    peak = rss0
    flood = int(a.rss_mib * 1024 * 1024) + (32 << 20)  # more than the memory allowed

    def attempt(kind, raw, name):
        nonlocal passed, failed, srv, peak
        try:
            if kind == 'ws':
                send_ws(srv.port, raw, srv, flood)
            else:
                send_http(srv.port, raw)
            if not srv.alive():
                raise Broke(f'the server exited with status {srv.proc.returncode}')
            passed += 1
        except (Broke, OSError) as e:
            failed += 1
            os.makedirs(failures_dir, exist_ok=True)
            path = os.path.join(failures_dir, f'{hashlib.sha1(raw).hexdigest()[:12]}.{kind}')
            with open(path, 'wb') as f:
                f.write(raw)
            print(f'FAIL  {name}: {e} (input kept as {path})', flush=True)
            if not srv.alive():  # go on with a new server
                srv = Server(a.cablefilm, a.scene, a.out_dir)
                srv.rss_limit_kib = limit

    def check_health(after):
        nonlocal failed, peak
        try:
            peak = max(peak, healthy(srv, limit))
        except (Broke, OSError) as e:
            failed += 1
            print(f'FAIL  health after {after}: {e}', flush=True)

    # 1. The corpus: seeds and regressions, each file once.
    corpus = sorted(f for f in os.listdir(CORPUS) if f.endswith(('.http', '.ws')))
    for name in corpus:
        with open(os.path.join(CORPUS, name), 'rb') as f:
            raw = f.read().replace(b'{PORT}', str(srv.port).encode())
        attempt('ws' if name.endswith('.ws') else 'http', raw, name)
    check_health('the corpus')
    print(f'corpus: {len(corpus)} inputs replayed', flush=True)

    # 2. Random inputs, from the seed: new ones and mutations of the corpus.
    rng = random.Random(a.seed)
    seeds = []
    for name in corpus:
        with open(os.path.join(CORPUS, name), 'rb') as f:
            seeds.append(('ws' if name.endswith('.ws') else 'http', f.read()))
    deadline = time.time() + a.seconds
    n = 0
    while time.time() < deadline:
        n += 1
        r = rng.random()
        if r < 0.45:
            kind, raw = 'http', make_http(rng, srv.port)
        elif r < 0.85:
            kind, raw = 'ws', make_ws(rng)
        else:
            kind, raw = rng.choice(seeds)
            raw = mutate(rng, raw.replace(b'{PORT}', str(srv.port).encode()))
        attempt(kind, raw, f'input {n} ({kind}, seed {a.seed})')
        if n % 25 == 0:
            check_health(f'input {n}')
    check_health(f'all {n} inputs')
    print(f'random: {n} inputs in {a.seconds:g} s (seed {a.seed}); resident memory {rss0} KiB '
          f'at start, {peak} KiB at most (limit {limit} KiB)', flush=True)
    code = srv.stop()
    if code != 0:
        failed += 1
        print(f'FAIL  SIGTERM: exit status {code}', flush=True)
    print(f'{passed} passed, {failed} failed')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
