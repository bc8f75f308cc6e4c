#!/usr/bin/python3
"""Real-browser test of `cablefilm live`: the page, its WebSocket, its controls.

    /usr/bin/python3 tests/live/browser_test.py --cablefilm ./build/cablefilm \\
        --scene scenes/polachek1963.toml --out-dir /tmp/live-test [--screenshots DIR]

Starts the server on a free port, drives Debian's headless chromium through selenium and
checks, waiting on the page's body dataset (frames, lastFrame, t, states) rather than sleeping:
  1. load: nothing requested outside the server; the first frame arrives over the WebSocket
  2. frames: t increases and the picture changes
  3. pause: /state says paused; the picture holds still; step advances one frame
  4. amplitude: the slider reaches /state; a refused value shows the server's error; after
     resuming the picture changes
  4b. heading: the current heading's dial reaches /state and a heading set elsewhere (-45)
     moves the dial to the same direction (315 degrees); a refused heading shows the server's
     error; without waves no wave heading
  4c. waves: on scenes/grounded_mooring.toml (waves, an end that follows them: every sea
     control shown) the wave heading's dial reaches /state and the waves and the current turn;
     a refused wave heading shows the server's error; the layout checks of 7 hold
  4d. system: on scenes/spread_mooring.toml (four lines, a vessel) the vessel's offsets shown
     and the controls it has not hidden; the offset reaches /state and moves the vessel; a
     refused offset shows the server's error; the layout checks of 7 hold
  5. keyboard: Space pauses and resumes, R restarts
  6. record: a film is recorded and its download link works
  7. layout: at 1400x900 and 1000x700 nothing overlaps or overflows sideways, and at 1000x700
     every control is in view (the panel does not scroll) and no figure is cut
  8. ends and colour range: the ends named by their kind; Reset range unlocks the range and
     brings it back to the tensions now
  9. errors: on a scene without a driven end, no amplitude or period; a recording that cannot
     be written says why; on a scene that blows up, the blow-up is shown until a restart;
     bound beyond loopback (0.0.0.0, visited over 127.0.0.1), the printed address's token
     opens the page, its WebSocket and its controls, and leaves the address bar
 10. serving: every route still answers, no console errors; SIGTERM exits 0 and the page says so
Prints one line per check and `N passed, M failed`; exits 1 on any failure.
"""
import argparse
import base64
import contextlib
import json
import os
import queue
import re
import signal
import struct
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request
import zlib

from selenium import webdriver
from selenium.common.exceptions import TimeoutException, WebDriverException
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

READY = re.compile(r'live view at (https?://[^\s/]+)/?(\?token=[0-9a-f]+)?\s*$')
CSV_HEADER = ('t,x_end,y_end,z_end,tension_start,tension_end,tension_max,link_max'
              ',fx_start,fy_start,fz_start,fx_end,fy_end,fz_end,angle_start,angle_end')


class Failure(Exception):
    pass


# ---- PNG decoding (stdlib only), to compare element screenshots pixel by pixel -------------
def png_pixels(data):
    """Returns (width, height, pixel bytes) of an 8-bit PNG."""
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise Failure('screenshot is not a PNG')
    pos, idat = 8, []
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b'IHDR':
            w, h, depth, ctype = struct.unpack('>IIBB', chunk[:10])
        elif kind == b'IDAT':
            idat.append(chunk)
    bpp = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    if depth != 8:
        raise Failure('screenshot PNG has bit depth %d' % depth)
    raw, stride = zlib.decompress(b''.join(idat)), w * bpp
    out, prev = bytearray(), bytearray(stride)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if f == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif f == 2:
            line = bytearray((a + b) & 255 for a, b in zip(line, prev))
        elif f == 3:
            for i in range(stride):
                line[i] = (line[i] + ((line[i - bpp] if i >= bpp else 0) + prev[i]) // 2) & 255
        elif f == 4:
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b, c = prev[i], prev[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += line
        prev = line
    return w, h, bytes(out), bpp


def compare(png_a, png_b):
    """How two PNG screenshots differ: (fraction of pixels, description)."""
    if png_a == png_b:
        return 0.0, 'identical'
    wa, ha, a, bpp = png_pixels(png_a)
    wb, hb, b, _ = png_pixels(png_b)
    if (wa, ha) != (wb, hb):
        return 1.0, 'sizes %dx%d and %dx%d' % (wa, ha, wb, hb)
    differ = [i for i in range(0, len(a), bpp) if a[i:i + bpp] != b[i:i + bpp]]
    if not differ:
        return 0.0, 'identical pixels'
    xs, ys = [i // bpp % wa for i in differ], [i // bpp // wa for i in differ]
    delta = max(abs(a[i + k] - b[i + k]) for i in differ for k in range(bpp))
    return len(differ) / (wa * ha), '%d pixels in x %d-%d, y %d-%d, up to %d levels apart' % (
        len(differ), min(xs), max(xs), min(ys), max(ys), delta)


# ---- the server ---------------------------------------------------------------------------
class Server:
    def __init__(self, args, scene=None, out_dir=None, log_name='server.log', extra=()):
        os.makedirs(args.out_dir, exist_ok=True)
        self.log_path = os.path.join(args.out_dir, log_name)
        self.log = open(self.log_path, 'w')
        cmd = [args.cablefilm, 'live', scene or args.scene, '--port', '0', '--size', '640x360',
               '--out', out_dir or args.out_dir, *extra]
        print('starting:', ' '.join(cmd), flush=True)
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=self.log, text=True)
        self.lines = queue.Queue()
        threading.Thread(target=self._read_stdout, daemon=True).start()
        deadline = time.monotonic() + args.start_timeout
        while True:
            try:
                line = self.lines.get(timeout=max(0.0, deadline - time.monotonic()))
            except queue.Empty:
                self.stop()
                raise Failure('no "live view at http://..." line on stdout after %g s; its log:\n%s'
                              % (args.start_timeout, self.tail()))
            if line is None:
                raise Failure('the server exited (status %s) before it was ready; its log:\n%s'
                              % (self.proc.wait(), self.tail()))
            m = READY.search(line)
            if m:
                self.origin = m.group(1)
                self.query = m.group(2) or ''  # ?token=... when bound beyond loopback
                print('server ready at', self.origin, flush=True)
                return

    def _read_stdout(self):
        for line in self.proc.stdout:
            self.log.write('[stdout] ' + line)
            self.log.flush()
            self.lines.put(line)
        self.lines.put(None)

    def tail(self, n=15):
        self.log.flush()
        with open(self.log_path, errors='replace') as f:
            return ''.join(f.readlines()[-n:])

    def stop(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()


def http_get(url, timeout=15):
    with urllib.request.urlopen(url, timeout=timeout) as r:
        return r.status, r.headers.get('Content-Type', ''), r.read()


# ---- the test -----------------------------------------------------------------------------
class BrowserTest:
    def __init__(self, args, server):
        self.args, self.server, self.origin = args, server, server.origin
        self.timeout = args.timeout
        opts = webdriver.ChromeOptions()
        opts.binary_location = args.chromium
        for a in ('--headless=new', '--no-sandbox', '--disable-gpu', '--window-size=1400,900'):
            opts.add_argument(a)
        opts.set_capability('goog:loggingPrefs', {'browser': 'ALL'})
        self.driver = webdriver.Chrome(service=Service(args.chromedriver), options=opts)
        self.driver.set_page_load_timeout(self.timeout)

    # helpers
    def state(self):
        return json.loads(http_get(self.origin + '/state')[2])

    def ds(self, key):
        return self.driver.execute_script('return document.body.dataset[arguments[0]]', key)

    def num(self, key, default=-1.0):
        v = self.ds(key)
        return float(v) if v not in (None, '') else default

    def wait(self, condition, what, timeout=None):
        try:
            return WebDriverWait(self.driver, timeout or self.timeout, poll_frequency=0.1).until(
                lambda _: condition())
        except TimeoutException:
            dataset = self.driver.execute_script('return JSON.stringify(document.body.dataset)')
            raise Failure('timed out after %g s waiting for %s (page: %s)' % (timeout or self.timeout, what, dataset))

    def frame_png(self):
        return self.driver.find_element(By.ID, 'frame').screenshot_as_png

    def text(self, id_):
        return self.driver.find_element(By.ID, id_).text

    def click(self, id_):
        self.driver.find_element(By.ID, id_).click()

    def screenshot(self, name):
        if not self.args.screenshots:
            return
        os.makedirs(self.args.screenshots, exist_ok=True)
        shot = self.driver.execute_cdp_cmd('Page.captureScreenshot', {'format': 'png', 'captureBeyondViewport': True})
        path = os.path.join(self.args.screenshots, name + '.png')
        with open(path, 'wb') as f:
            f.write(base64.b64decode(shot['data']))

    def keep(self, name, png):
        with open(os.path.join(self.args.out_dir, name), 'wb') as f:
            f.write(png)

    def wait_frames(self, count, what):
        """Waits for `count` more frames and a later t; returns the new t."""
        f0, t0 = self.num('frames'), self.num('t')
        self.wait(lambda: self.num('frames') >= f0 + count and self.num('t') > t0, what)
        return self.num('t')

    def wait_still(self):
        """Waits until t has not changed for 1 s of polling and 3 state messages."""
        seen = {'t': None}
        def still():
            t, states, now = self.ds('t'), self.num('states'), time.monotonic()
            if t != seen['t']:
                seen.update(t=t, states=states, since=now)
                return False
            return now - seen['since'] >= 1.0 and states >= seen['states'] + 3
        self.wait(still, 't to stop changing')
        return float(seen['t'])

    # 1
    def check_load(self):
        self.driver.get(self.origin + '/')
        self.wait(lambda: self.num('frames') >= 1, 'the first frame')
        self.wait(lambda: self.driver.execute_script(
            'return document.getElementById("frame").naturalWidth') > 0, '#frame to have a natural width')
        self.wait(lambda: self.ds('transport') == 'websocket', 'the WebSocket (the page fell back to polling?)')
        names = self.driver.execute_script(
            "return performance.getEntriesByType('navigation').concat("
            "performance.getEntriesByType('resource')).map(e => e.name)")
        foreign = [n for n in names if not (n.startswith(self.origin + '/') or n.startswith('blob:' + self.origin + '/'))]
        if foreign:
            raise Failure('requests outside the server: %s' % foreign)
        width = self.driver.execute_script('return document.getElementById("frame").naturalWidth')
        self.screenshot('01-loaded')
        return '%d requests, all to %s; first frame %s px wide' % (len(names), self.origin, width)

    # 2
    def check_frames_change(self):
        t0, a = self.num('t'), self.frame_png()
        t1 = self.wait_frames(10, '10 more frames')
        b = self.frame_png()
        d, _ = compare(a, b)
        if d == 0:
            self.keep('frames-a.png', a), self.keep('frames-b.png', b)
            raise Failure('the picture did not change from t = %g to %g s' % (t0, t1))
        self.screenshot('02-running')
        return 't %.3f -> %.3f s, %.1f %% of pixels changed' % (t0, t1, 100 * d)

    # 3
    def check_pause(self):
        self.click('pause')
        self.wait(lambda: self.state()['paused'] is True, '/state to say paused')
        self.wait(lambda: self.text('pause') == 'Resume' and self.ds('paused') == 'true',
                  'the page to show it is paused')
        t_page = self.wait_still()
        t_state = self.state()['t']
        a = self.frame_png()
        n0 = self.num('states')
        self.wait(lambda: self.num('states') >= n0 + 3, '3 more state messages')
        b = self.frame_png()
        if self.state()['t'] != t_state:
            raise Failure('/state t moved while paused: %g -> %g' % (t_state, self.state()['t']))
        d, how = compare(a, b)
        if d:
            self.keep('paused-a.png', a), self.keep('paused-b.png', b)
            raise Failure('the picture changed while paused: %s (kept in %s/paused-[ab].png)' % (
                how, self.args.out_dir))
        self.screenshot('03-paused')
        # one step while paused
        frame0 = self.num('lastFrame')
        self.wait(lambda: self.driver.find_element(By.ID, 'step').is_enabled(), '#step to be enabled')
        self.click('step')
        self.wait(lambda: self.num('lastFrame') > frame0 and float(self.ds('t')) > t_page, 'a stepped frame')
        if not self.state()['paused']:
            raise Failure('a step resumed the simulation')
        return 'paused at t = %.3f s (state %.3f s); still picture; step -> t = %.3f s' % (
            t_page, t_state, self.num("t"))

    # 4
    def check_amplitude(self):
        s = self.state()
        lo, hi = s['limits']['amplitude_scale']
        target = round(lo + 0.8 * (hi - lo), 2)
        if abs(s['amplitude_scale'] - target) < 1e-9:
            target = round(lo + 0.3 * (hi - lo), 2)
        before = self.frame_png()
        self.driver.execute_script(
            'const e = document.getElementById("amplitude"); e.value = arguments[0];'
            'e.dispatchEvent(new Event("change", {bubbles: true}));', target)
        self.wait(lambda: abs(self.state()['amplitude_scale'] - target) < 1e-6 * max(1, target),
                  '/state amplitude_scale = %g' % target)
        self.wait(lambda: self.text('amplitude-out') == '%.2f×' % target, 'the page to show amplitude %g' % target)
        # a refused control: the page shows the server's message, nothing changes
        speed = self.state()['speed']
        self.driver.execute_script('window.cablefilm.control({speed: 50})')
        self.wait(lambda: 'speed' in self.text('message'), 'the error message about speed')
        if self.state()['speed'] != speed:
            raise Failure('a refused speed changed the speed')
        message = self.text('message')
        self.screenshot('04-error-message')
        # resume: the picture moves on
        self.click('pause')
        self.wait(lambda: self.state()['paused'] is False, '/state to say running')
        t1 = self.wait_frames(10, '10 frames after resuming')
        after = self.frame_png()
        d, _ = compare(before, after)
        if d == 0:
            raise Failure('the picture did not change after the amplitude change and resuming')
        self.screenshot('04-amplitude')
        return 'amplitude_scale -> %g; error shown: "%s"; t = %.3f s, %.1f %% of pixels changed' % (
            target, message, t1, 100 * d)

    # 4b
    def check_heading(self):
        if self.driver.find_element(By.ID, 'wave_heading').is_displayed():
            raise Failure('a wave heading on a scene without waves')
        s = self.state()
        if s['current_heading'] != 0 or s['limits']['current_heading'] != [-360, 360]:
            raise Failure('the scene\'s current heading %r, limits %r' % (
                s['current_heading'], s['limits']['current_heading']))
        if self.text('current_heading-out') != '0°':
            raise Failure('the dial says %r for the scene\'s 0 degrees' % self.text('current_heading-out'))
        self.driver.execute_script(
            'const e = document.getElementById("current_heading"); e.value = arguments[0];'
            'e.dispatchEvent(new Event("change", {bubbles: true}));', 270)
        self.wait(lambda: self.state()['current_heading'] == 270, '/state current_heading = 270')
        self.wait(lambda: self.text('current_heading-out') == '270°', 'the page to show 270°')
        # Set from elsewhere (a script, another viewer): the dial shows the same direction.
        self.driver.execute_script('window.cablefilm.control({current_heading: -45})')
        self.wait(lambda: self.state()['current_heading'] == -45, '/state current_heading = -45')
        self.wait(lambda: self.text('current_heading-out') == '315°' and self.driver.execute_script(
            'return document.getElementById("current_heading").value') == '315',
            'the dial at 315° for -45')
        self.driver.execute_script('window.cablefilm.control({current_heading: 400})')
        self.wait(lambda: 'current_heading' in self.text('message'), 'the error about the heading')
        message = self.text('message')
        if self.state()['current_heading'] != -45:
            raise Failure('a refused heading changed the heading')
        self.screenshot('04b-heading')
        return 'dial 270 -> /state; -45 shown as 315°; refused: "%s"' % message

    # 4c
    @contextlib.contextmanager
    def on_scene(self, name, label):
        """The page of another shipped scene's server (scenes/`name`, its files and log under
        `label`) at 1400x900 for the checks inside the `with`; then the main server's page."""
        scene = os.path.join(os.path.dirname(os.path.abspath(self.args.scene)), name)
        server = Server(self.args, scene, os.path.join(self.args.out_dir, label),
                        'server-%s.log' % label)
        origin = self.origin
        try:
            self.origin = server.origin
            self.driver.set_window_size(1400, 900)
            self.driver.get(server.origin + '/')
            self.wait(lambda: self.num('frames') >= 1 and self.ds('transport') == 'websocket', 'the page')
            yield server
        finally:
            self.origin = origin
            self.driver.get('about:blank')
            server.stop()
            self.driver.set_window_size(1400, 900)
            self.driver.get(self.origin + '/')
            self.wait(lambda: self.num('frames') >= 1 and self.ds('transport') == 'websocket', 'the main page again')

    def shown(self, id_):
        return self.driver.find_element(By.ID, id_).is_displayed()

    def check_waves(self):
        """The fullest panel: scenes/grounded_mooring.toml (waves, an end that follows them):
        the wave heading's dial reaches /state and turns the waves; a refused heading says why;
        every control fits at 1000x700 and 1400x900."""
        with self.on_scene('grounded_mooring.toml', 'waves'):
            for id_ in ('current_heading', 'wave_height', 'wave_period', 'wave_heading'):
                if not self.driver.find_element(By.ID, id_).is_displayed():
                    raise Failure('the %s control is hidden on a scene with waves' % id_)
            s = self.state()
            if s['wave_heading'] != 0 or s['limits']['wave_heading'] != [-360, 360]:
                raise Failure('the scene\'s wave heading %r, limits %r' % (
                    s['wave_heading'], s['limits']['wave_heading']))
            self.driver.execute_script(
                'const e = document.getElementById("wave_heading"); e.value = arguments[0];'
                'e.dispatchEvent(new Event("change", {bubbles: true}));', 30)
            self.wait(lambda: self.state()['wave_heading'] == 30, '/state wave_heading = 30')
            self.wait(lambda: self.text('wave_heading-out') == '30°', 'the page to show 30°')
            # The waves turn over one wave period (10 s) of simulated time, at 5x real time.
            self.driver.execute_script('window.cablefilm.control({speed: 5, current_heading: 90})')
            self.wait(lambda: abs(self.state()['wave_heading_now'] - 30) < 1e-9 and
                      abs(self.state()['current_heading_now'] - 90) < 1e-9,
                      'the waves turned to 30° and the current to 90°', timeout=max(self.timeout, 60))
            # Every control fits (before the error below fills the header's message).
            layout = self._layout('04c-waves-layout')
            self.driver.execute_script('window.cablefilm.control({wave_heading: -400})')
            self.wait(lambda: 'wave_heading' in self.text('message'), 'the error about the heading')
            message = self.text('message')
            if self.state()['wave_heading'] != 30:
                raise Failure('a refused wave heading changed it')
            self.screenshot('04c-waves')
            return 'wave heading 30 -> /state and turned; refused: "%s"; %s' % (message, layout)

    # 4d
    def check_system(self):
        """A system (scenes/spread_mooring.toml: four lines, the vessel's fairleads in eq.
        (3)'s orbit, no free body): the driven motion's amplitude and period and the vessel's
        offsets shown, the bodies' force and the waves' controls hidden; the offset slider
        reaches /state and the vessel moves there; a refused offset shows the server's error
        and changes nothing; the layout checks of 7 hold."""
        with self.on_scene('spread_mooring.toml', 'system'):
            s = self.state()
            names = [line['name'] for line in s.get('lines', [])]
            if names != ['leg1_lower', 'leg1_upper', 'leg2', 'leg3']:
                raise Failure('/state: lines %r' % names)
            for id_ in ('offset_x', 'offset_z', 'amplitude', 'period'):
                if not self.shown(id_):
                    raise Failure('the %s control is hidden on a system that has it' % id_)
            for id_ in ('force_x', 'force_z', 'wave_height', 'wave_heading'):
                if self.shown(id_):
                    raise Failure('the %s control is shown on a system without it' % id_)
            if self.text('sea-title').lower() != 'motion and sea':  # shown in capitals
                raise Failure('the panel is titled %r' % self.text('sea-title'))
            self.driver.execute_script(
                'const e = document.getElementById("offset_x"); e.value = arguments[0];'
                'e.dispatchEvent(new Event("change", {bubbles: true}));', -6)
            self.wait(lambda: self.state()['offset_x'] == -6, '/state offset_x = -6')
            self.wait(lambda: self.text('offset_x-out') == '-6.0 m', 'the page to show -6.0 m')
            # The offset ramps over 5 s of simulated time (at most 2 m/s), at 5x real time.
            self.driver.execute_script('window.cablefilm.control({speed: 5})')
            self.wait(lambda: self.state()['offset_x_now'] == -6, 'the vessel at -6 m',
                      timeout=max(self.timeout, 60))
            layout = self._layout('04d-system-layout')
            limit = s['limits']['offset'][1]
            self.driver.execute_script('window.cablefilm.control({offset_x: arguments[0]})', limit + 1)
            self.wait(lambda: 'offset_x' in self.text('message'), 'the error about the offset')
            message = self.text('message')
            if self.state()['offset_x'] != -6:
                raise Failure('a refused offset changed it')
            self.screenshot('04d-system')
            return 'lines %s; offset -6 m -> /state and the vessel; refused: "%s"; %s' % (
                ', '.join(names), message, layout)

    # 5
    def check_keyboard(self):
        keys = lambda k: self.driver.find_element(By.TAG_NAME, 'body').send_keys(k)
        paused = self.state()['paused']
        keys(' ')
        self.wait(lambda: self.state()['paused'] is (not paused), 'Space to toggle pause')
        keys(' ')
        self.wait(lambda: self.state()['paused'] is paused, 'Space to toggle pause back')
        self.wait_frames(5, 'frames before the restart')
        t0 = self.state()['t']
        keys('r')
        self.wait(lambda: self.state()['t'] < t0, 'R to restart (t back below %.3f s)' % t0)
        self.wait_frames(5, 'frames after the restart')
        return 'Space paused and resumed; R restarted from t = %.3f s' % t0

    # 6
    def check_record(self):
        self.click('record')
        self.wait(lambda: self.state()['recording'] is True, '/state to say recording')
        self.wait(lambda: self.driver.find_element(By.ID, 'record').get_attribute('aria-pressed') == 'true',
                  'the record button to show recording')
        self.screenshot('06-recording')
        self.wait_frames(15, '15 frames while recording')
        before = len(self.state()['recordings'])
        self.click('record')
        self.wait(lambda: not self.state()['recording'] and len(self.state()['recordings']) > before,
                  '/state to list the new recording')
        rec = self.state()['recordings'][-1]
        link = self.wait(lambda: self.driver.execute_script(
            'const a = document.querySelector("#recordings a"); return a && a.href'),
            'the download link (the newest first)')
        if not link.endswith(rec['url']):
            raise Failure('the newest link is %s, /state says %s' % (link, rec['url']))
        status, ctype, body = http_get(link, timeout=60)
        if status != 200 or len(body) < 100 or body[4:8] != b'ftyp':
            raise Failure('%s: status %d, %d bytes, not an MP4' % (link, status, len(body)))
        self.screenshot('06-recorded')
        return '%s, %d frames, %d bytes' % (rec['name'], rec['frames'], len(body))

    # 7
    def check_layout(self):
        return self._layout('07-layout')

    # The layout checks at 1000x700 and 1400x900, a screenshot of each named `prefix`-WxH.
    def _layout(self, prefix):
        notes = []
        for w, h in ((1000, 700), (1400, 900)):
            self.driver.set_window_size(w, h)
            self.wait(lambda: self.driver.execute_script('return window.outerWidth') == w, 'the resize')
            self.wait_frames(2, 'frames after resizing')
            r = self.driver.execute_script('''
                const box = (s) => { const r = document.querySelector(s).getBoundingClientRect();
                                     return [r.left, r.top, r.right, r.bottom]; };
                return {frame: box('.frame-box'), stats: box('.stats'), panel: box('.panel'),
                        header: box('.top'), vw: innerWidth, sw: document.documentElement.scrollWidth};''')
            over = lambda a, b: a[0] < b[2] - 0.5 and b[0] < a[2] - 0.5 and a[1] < b[3] - 0.5 and b[1] < a[3] - 0.5
            for x, y in (('frame', 'stats'), ('frame', 'panel'), ('stats', 'panel'), ('header', 'frame'),
                         ('header', 'panel')):
                if over(r[x], r[y]):
                    raise Failure('at %dx%d %s %s overlaps %s %s' % (w, h, x, r[x], y, r[y]))
            if r['sw'] > r['vw']:
                raise Failure('at %dx%d the page is %d px wide in a %d px window' % (w, h, r['sw'], r['vw']))
            frame_h = r['frame'][3] - r['frame'][1]
            if frame_h < 0.4 * (r['vw'] * h / w):
                raise Failure('at %dx%d the frame is only %d px high' % (w, h, frame_h))
            # Every control in view (the panel does not scroll, with a recording listed) and
            # no figure, label or link cut short.
            fit = self.driver.execute_script('''
                const p = document.querySelector('.panel');
                const cut = [...document.querySelectorAll(
                    '.stat .label, .stat .value, .stat .sub, .card h2, .control label, .control output, .links a, .top h1')]
                  .filter((e) => e.offsetParent && e.scrollWidth > e.clientWidth + 1)
                  .map((e) => (e.id || e.className || e.tagName) + ': ' + e.textContent.trim());
                return {panel: [p.scrollHeight, p.clientHeight], page: [document.documentElement.scrollHeight, innerHeight],
                        cut: cut, recordings: document.querySelectorAll('#recordings li').length};''')
            if fit['panel'][0] > fit['panel'][1] + 1:
                raise Failure('at %dx%d the panel needs %d px in %d (it scrolls)' % (w, h, *fit['panel']))
            if fit['page'][0] > fit['page'][1] + 1:
                raise Failure('at %dx%d the page is %d px high in a %d px window' % (w, h, *fit['page']))
            if fit['cut']:
                raise Failure('at %dx%d cut short: %s' % (w, h, fit['cut']))
            self.screenshot('%s-%dx%d' % (prefix, w, h))
            notes.append('%dx%d frame %dx%d' % (w, h, r['frame'][2] - r['frame'][0], frame_h))
        return ', '.join(notes)

    # 8
    def check_ends_and_range(self):
        self.driver.set_window_size(1400, 900)
        start, end = self.text('start-label'), self.text('end-label')
        if (start, end) != ('Fixed end', 'Moving end'):
            raise Failure('the ends are called %r and %r (the scene: a fixed anchor, a moving fairlead)' % (start, end))
        if not self.driver.find_element(By.ID, 'amplitude').is_displayed():
            raise Failure('the amplitude is hidden on a scene with a driven end')
        # A range stretched far past the tensions (as a snap leaves it), locked.
        self.driver.execute_script('window.cablefilm.control({tension_range: [0, 900000]})')
        self.wait(lambda: self.state()['range']['max'] == 900000 and self.state()['range']['locked'],
                  'the stretched range')
        self.wait(lambda: self.driver.find_element(By.ID, 'lock-range').is_selected(), 'the lock box ticked')
        self.click('reset-range')
        self.wait(lambda: not self.state()['range']['locked'], 'Reset range to unlock the range')
        st = self.state()
        if not st['range']['max'] < 4 * st['tension']['max']:
            raise Failure('after Reset range the range is %s for tensions up to %.0f N' % (st['range'], st['tension']['max']))
        self.wait(lambda: not self.driver.find_element(By.ID, 'lock-range').is_selected(), 'the lock box cleared')
        # Unlocked, the range grows again with the tensions after the reset (up to the cycle's peak
        # within a period): the label is compared with the range as the server has it now.
        self.wait(lambda: self.text('range-max') == '%.2f kN' % (self.state()['range']['max'] / 1000),
                  'the colour bar label')
        return 'ends "%s", "%s"; range reset to %.0f N (then %s)' % (start, end, st['range']['max'],
                                                                     self.text('range-max'))

    # 9
    def check_errors(self):
        notes = []
        with open(self.args.scene) as f:
            text = f.read()
        # The fairlead held still: no driven end. Its films go under a regular file: they fail.
        still = re.sub(r'^\[ends\.end\].*?(?=^\[)', '[ends.end]\nposition = [80.0, 30.48]\nmotion = "fixed"\n\n',
                       text, flags=re.DOTALL | re.MULTILINE)
        # The fairlead swung 80 m every 2 s: the line is torn apart within seconds.
        torn = text.replace('x_amplitudes = [1.8288, 0.0]', 'x_amplitudes = [80.0, 0.0]').replace(
            'period = 10.0', 'period = 2.0')
        if torn == text or still == text:
            raise Failure('the scene is not the one these variants are made from')
        paths = {}
        for name, body in (('still_fairlead.toml', still), ('torn_line.toml', torn)):
            paths[name] = os.path.join(self.args.out_dir, name)
            with open(paths[name], 'w') as f:
                f.write(body)
        blocker = os.path.join(self.args.out_dir, 'not-a-folder')
        with open(blocker, 'w') as f:
            f.write('a file where the films would go\n')
        for scene, check in ((paths['still_fairlead.toml'], self._errors_still),
                             (paths['torn_line.toml'], self._errors_torn)):
            server = Server(self.args, scene, os.path.join(blocker, 'films'), 'server-' + os.path.basename(scene) + '.log')
            try:
                origin = self.origin
                self.origin = server.origin
                self.driver.get(server.origin + '/')
                self.wait(lambda: self.num('frames') >= 1 and self.ds('transport') == 'websocket', 'the page')
                notes.append(check())
            finally:
                self.origin = origin
                self.driver.get('about:blank')  # before the server goes: no page left to miss it
                server.stop()
        self.driver.get(self.origin + '/')
        self.wait(lambda: self.num('frames') >= 1 and self.ds('transport') == 'websocket', 'the main page again')
        # Drained here: the servers of these scenes are gone, the page of the main one is not.
        severe = [e['message'] for e in self.driver.get_log('browser')
                  if e['level'] == 'SEVERE' and self.origin in e['message']]
        if severe:
            raise Failure('console errors: %s' % severe)
        return '; '.join(notes)

    def _errors_still(self):
        for id_ in ('amplitude', 'period'):
            if self.driver.find_element(By.ID, id_).is_displayed():
                raise Failure('the %s control is shown on a scene without a driven end' % id_)
        ends = (self.text('start-label'), self.text('end-label'))
        if ends != ('Fixed end', 'Fixed end'):
            raise Failure('the ends are called %r' % (ends,))
        self.click('record')
        self.wait(lambda: 'record_error' in self.state(), '/state to report the failed recording')
        alert = self.wait(lambda: self.driver.find_element(By.ID, 'alert').is_displayed()
                          and self.text('alert'), 'the page to show the failed recording')
        if 'Recording failed' not in alert or 'not-a-folder' not in alert:
            raise Failure('the alert says %r' % alert)
        self.screenshot('09-record-error')
        return 'no amplitude/period; "%s"' % alert.split('\n')[0][:80]

    def _errors_torn(self):
        self.wait(lambda: 'error' in self.state(), 'the blow-up', timeout=max(self.timeout, 60))
        alert = self.wait(lambda: self.driver.find_element(By.ID, 'alert').is_displayed()
                          and self.text('alert'), 'the page to show the blow-up')
        if 'Simulation stopped' not in alert or 'blow-up' not in alert:
            raise Failure('the alert says %r' % alert)
        self.screenshot('09-blow-up')
        self.click('restart')
        self.wait(lambda: not self.driver.find_element(By.ID, 'alert').is_displayed(), 'the alert to go after a restart')
        return '"%s"' % alert.split('\n')[0][:80]

    def check_token(self):
        server = Server(self.args, out_dir=os.path.join(self.args.out_dir, 'token'),
                        log_name='server-token.log', extra=('--bind', '0.0.0.0'))
        try:
            if not server.query.startswith('?token='):
                raise Failure('bound to 0.0.0.0 the printed address has no token')
            local = server.origin.replace('0.0.0.0', '127.0.0.1')
            try:
                http_get(local + '/state')
                raise Failure('/state without the token was served')
            except urllib.error.HTTPError as e:
                if e.code != 401:
                    raise Failure('/state without the token answered %d' % e.code)
            self.driver.get(local + '/' + server.query)
            self.wait(lambda: self.num('frames') >= 3 and self.ds('transport') == 'websocket',
                      'frames over the WebSocket with the token')
            if 'token' in self.driver.current_url:
                raise Failure('the token stays in the address bar: %s' % self.driver.current_url)
            if 'token' in self.driver.execute_script('return document.cookie'):
                raise Failure('the page script can read the token cookie (not HttpOnly)')
            self.driver.execute_script('window.cablefilm.control({pause: true})')
            self.wait(lambda: self.ds('paused') == 'true', 'a control to be taken with the token')
            self.driver.get(local + '/state')  # the cookie opens the rest of the server too
            if '"paused":true' not in self.driver.page_source.replace(' ', ''):
                raise Failure('/state with the cookie: %s' % self.driver.page_source[:200])
            return 'token in the printed address; page, WebSocket and controls work; address bar clean'
        finally:
            self.driver.get('about:blank')
            server.stop()
            self.driver.get(self.origin + '/')
            self.wait(lambda: self.num('frames') >= 1 and self.ds('transport') == 'websocket', 'the main page again')
            self.driver.get_log('browser')  # the token server's page is gone: its errors with it

    # 10
    def check_serving_and_sigterm(self):
        o, notes = self.origin, []
        for path, kind, magic in (('/', 'text/html', b'<!DOCTYPE html>'), ('/app.js', 'javascript', b''),
                                  ('/style.css', 'text/css', b''), ('/frame.jpg', 'image/', b'\xff\xd8\xff'),
                                  ('/snapshot.png', 'image/png', b'\x89PNG'), ('/state', 'json', b'{'),
                                  ('/timeseries.csv', '', CSV_HEADER.encode())):
            status, ctype, body = http_get(o + path)
            if self.args.mock and path == '/frame.jpg':
                magic = b'\x89PNG'  # the mock sends PNGs
            if status != 200 or kind not in ctype or not body.startswith(magic):
                raise Failure('%s: status %d, type %r, starts %r' % (path, status, ctype, body[:16]))
        rows = http_get(o + '/timeseries.csv')[2].decode().strip().split('\n')
        notes.append('routes ok, %d CSV rows' % (len(rows) - 1))
        with urllib.request.urlopen(o + '/stream.mjpg', timeout=15) as r:
            ctype = r.headers.get('Content-Type', '')
            head = r.read(4096)
        if 'multipart/x-mixed-replace' not in ctype or b'Content-Type' not in head:
            raise Failure('/stream.mjpg: type %r, starts %r' % (ctype, head[:60]))
        self.wait_frames(5, 'frames still arriving')
        severe = [e['message'] for e in self.driver.get_log('browser') if e['level'] == 'SEVERE']
        if severe:
            raise Failure('console errors: %s' % severe)
        proc = self.server.proc
        proc.send_signal(signal.SIGTERM)
        try:
            rc = proc.wait(timeout=self.timeout)
        except subprocess.TimeoutExpired:
            raise Failure('the server did not exit within %g s of SIGTERM' % self.timeout)
        if rc != 0:
            raise Failure('the server exited with status %d after SIGTERM' % rc)
        self.wait(lambda: self.ds('transport') != 'websocket', 'the page to notice the server is gone')
        status = self.text('status')
        self.screenshot('08-server-gone')
        notes.append('SIGTERM -> exit 0; page says "%s"' % status)
        return '; '.join(notes)


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('--cablefilm', required=True, help='the cablefilm binary')
    p.add_argument('--scene', required=True)
    p.add_argument('--out-dir', required=True, help="the server's --out folder; also logs")
    p.add_argument('--screenshots', help='save full-page screenshots here')
    p.add_argument('--timeout', type=float, default=30, help='seconds for each wait (default 30)')
    p.add_argument('--start-timeout', type=float, default=120, help='seconds for the server to be ready')
    p.add_argument('--chromium', default='/usr/bin/chromium')
    p.add_argument('--chromedriver', default='/usr/bin/chromedriver')
    p.add_argument('--mock', action='store_true', help='the server is tests/live/mock_server.py (PNG frames)')
    args = p.parse_args()

    passed, failed = 0, 0
    server = test = None
    try:
        server = Server(args)
        test = BrowserTest(args, server)
        checks = [('load', test.check_load), ('frames change', test.check_frames_change),
                  ('pause', test.check_pause), ('amplitude', test.check_amplitude),
                  ('heading', test.check_heading), ('waves', test.check_waves),
                  ('system', test.check_system),
                  ('keyboard', test.check_keyboard), ('record', test.check_record), ('layout', test.check_layout),
                  ('ends and range', test.check_ends_and_range), ('errors', test.check_errors),
                  ('token', test.check_token),
                  ('serving and SIGTERM', test.check_serving_and_sigterm)]
        for name, check in checks:
            start = time.monotonic()
            try:
                note = check()
                passed += 1
                print('PASS %-20s %5.1f s  %s' % (name, time.monotonic() - start, note), flush=True)
            except (Failure, WebDriverException, urllib.error.URLError, OSError, KeyError, ValueError) as e:
                failed += 1
                msg = str(e).strip().split('\n')[0] if not isinstance(e, Failure) else str(e)
                print('FAIL %-20s %5.1f s  %s: %s' % (name, time.monotonic() - start,
                                                      type(e).__name__, msg), flush=True)
                if name == 'load':
                    failed += len(checks) - 1
                    print('     (the page did not load: the other checks are not run)')
                    break
    except (Failure, WebDriverException) as e:
        failed += 1
        print('FAIL setup: %s' % e, flush=True)
    finally:
        if test:
            test.driver.quit()
        if server:
            server.stop()
            if failed:
                print('--- last lines of %s ---\n%s' % (server.log_path, server.tail()), end='')
    if args.screenshots and passed:
        print('screenshots in', args.screenshots)
    print('%d passed, %d failed' % (passed, failed))
    sys.exit(1 if failed else 0)


if __name__ == '__main__':
    main()
