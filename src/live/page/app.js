// cablefilm live: shows the server's JPEG frames and state, sends controls back.
// Frames and state come over the WebSocket /ws; without one the page polls /state and
// /frame.jpg. Controls go over the WebSocket when it is open, else POST /control.
'use strict';

const $ = (id) => document.getElementById(id);
const body = document.body;
const img = $('frame');

const COLORMAPS = {  // CSS approximations of the server's maps, for the colour bar only
  viridis: ['#440154', '#414487', '#2a788e', '#22a884', '#7ad151', '#fde725'],
  cividis: ['#00224e', '#35456c', '#666970', '#948e77', '#c8b866', '#fee838'],
  magma: ['#000004', '#3b0f70', '#8c2981', '#de4968', '#fe9f6d', '#fcfdbf'],
  inferno: ['#000004', '#420a68', '#932667', '#dd513a', '#fca50a', '#fcffa4'],
  plasma: ['#0d0887', '#6a00a8', '#b12a90', '#e16462', '#fca636', '#f0f921'],
};
const HEADER_BYTES = 24;  // uint64 frame, float64 t, uint64 control sequence (little endian)
const POLL_MS = 200;

let state = null;          // the newest state from the server
let ws = null;
let wsOpened = false;      // has any WebSocket connection ever opened
let retryMs = 500;         // reconnection backoff, doubled up to 8 s
let pollTimer = null;
const pending = [];        // resolvers of controls sent over the WebSocket, answered in order

// ---- formatting -------------------------------------------------------------------------
const kN = (n) => (n == null ? '–' : (n / 1000).toFixed(2) + ' kN');
const turn = (v) => ((v % 360) + 360) % 360;  // a heading in [0, 360): the same direction
const degrees = (v) => turn(Math.round(v)).toFixed(0) + '°';
const secs = (s) => (s == null ? '–' : s.toFixed(2) + ' s');
const fmt = {
  speed: (v) => v.toFixed(v < 1 ? 2 : 1) + '×',
  amplitude_scale: (v) => v.toFixed(2) + '×',
  period: (v) => v.toFixed(1) + ' s',
  current: (v) => (v > 0 ? '+' : '') + v.toFixed(2) + ' m/s',
  current_heading: degrees,
  wave_height: (v) => v.toFixed(2) + ' m',
  wave_period: (v) => v.toFixed(1) + ' s',
  wave_heading: degrees,
  offset_x: (v) => (v > 0 ? '+' : '') + v.toFixed(1) + ' m',
  offset_z: (v) => (v > 0 ? '+' : '') + v.toFixed(1) + ' m',
  force_x: (v) => (v > 0 ? '+' : '') + (v / 1000).toFixed(0) + ' kN',
  force_z: (v) => (v > 0 ? '+' : '') + (v / 1000).toFixed(0) + ' kN',
};

// ---- frames -----------------------------------------------------------------------------
// A frame that arrives while the previous one is still decoding replaces the queued one:
// the picture never falls behind, and the dataset describes the frame on screen. A frame
// the same as the last (same number and control sequence: sent again while paused) is
// counted but not decoded again, so a paused picture stays exactly still.
let received = 0;
let decoding = false;
let queued = null;         // {blob, key, frame, t}
let lastKey = null;
let shownUrl = null;
let onScreen = null;
const fpsTimes = [];

function showFrame(blob, frame, t, seq) {
  received += 1;
  const key = frame + ':' + seq;
  if (key === lastKey) {
    if (!decoding) body.dataset.frames = received;
    return;
  }
  lastKey = key;
  queued = { blob, frame, t };
  if (!decoding) nextFrame();
}

// Each frame is decoded off screen first, then shown: the visible image never goes blank
// (nor its naturalWidth to 0) while the next one loads.
const loader = new Image();

function nextFrame() {
  if (!queued) { decoding = false; return; }
  decoding = true;
  onScreen = queued;
  queued = null;
  loader.src = URL.createObjectURL(onScreen.blob);
  loader.decode().then(onDecoded, () => {
    URL.revokeObjectURL(loader.src);
    nextFrame();
  });
}

function onDecoded() {
  img.src = loader.src;  // already decoded: shown at once
  if (shownUrl) URL.revokeObjectURL(shownUrl);
  shownUrl = loader.src;
  body.dataset.frames = received;
  if (onScreen.frame != null) body.dataset.lastFrame = onScreen.frame;
  if (onScreen.t != null) { body.dataset.t = onScreen.t; $('t').textContent = secs(onScreen.t); }
  $('placeholder').hidden = true;
  const now = performance.now();
  fpsTimes.push(now);
  while (fpsTimes.length && fpsTimes[0] < now - 2000) fpsTimes.shift();
  nextFrame();
}

function onBinary(buf) {
  if (buf.byteLength <= HEADER_BYTES) return;
  const view = new DataView(buf);
  const frame = Number(view.getBigUint64(0, true));
  const t = view.getFloat64(8, true);
  const seq = Number(view.getBigUint64(16, true));
  showFrame(new Blob([buf.slice(HEADER_BYTES)], { type: 'image/jpeg' }), frame, t, seq);
}

// ---- state ------------------------------------------------------------------------------
function applyState(s) {
  state = s;
  body.dataset.states = Number(body.dataset.states) + 1;
  body.dataset.paused = s.paused;
  if (s.title) { $('title').textContent = s.title; document.title = s.title + ' · cablefilm live'; }
  $('viewers').textContent = s.viewers > 1 ? s.viewers + ' viewers' : '';
  if (s.width && s.height) img.parentElement.style.setProperty('--aspect', s.width + ' / ' + s.height);
  body.dataset.space = !!s.space;
  $('orbit-help').hidden = !s.space;
  if (!wsOpen() && !onScreen) $('t').textContent = secs(s.t);  // polling: t comes with the state
  $('frame-note').textContent = (s.paused ? 'paused at frame ' : 'frame ') + s.frame;
  // The ends by their kind, as the film's legend names them (fixed, moving, free).
  const E = s.ends || {};
  const endName = (kind, which) => (kind ? kind[0].toUpperCase() + kind.slice(1) + ' end' : which);
  $('start-label').textContent = endName(E.start, 'Start');
  $('end-label').textContent = endName(E.end, 'End');
  $('start-label').title = 'tension in the first link, at the ' + (E.start || 'start') + ' end';
  $('end-label').title = 'tension in the last link, at the ' + (E.end || 'other') + ' end';
  showAlert(s);
  const T = s.tension || {};
  $('t-start').textContent = kN(T.start);
  $('t-end').textContent = kN(T.end);
  $('t-max').textContent = kN(T.max);
  $('t-max-link').textContent = T.link_max == null ? '' : 'in link ' + T.link_max;
  if (s.lines && s.lines.length > 1) {
    // Several lines: the two most loaded now in the end boxes, the largest of all in Maximum.
    const top = s.lines.slice().sort((a, b) => b.max - a.max);
    $('start-label').textContent = top[0] ? top[0].name : 'Line';
    $('t-start').textContent = top[0] ? kN(top[0].max) : '–';
    $('start-label').title = 'the most loaded line now: its largest link tension';
    $('end-label').textContent = top[1] ? top[1].name : '';
    $('t-end').textContent = top[1] ? kN(top[1].max) : '';
    $('end-label').title = 'the second most loaded line now';
    $('t-start-sub').textContent = 'most loaded now';
    $('t-end-sub').textContent = top[1] ? 'next most loaded' : '';
    const line = top[0] ? ' of ' + top[0].name : '';
    $('t-max-link').textContent = T.link_max == null ? '' : 'link ' + T.link_max + line;
  }
  const P = s.peak || {};
  $('peak').textContent = kN(P.value);
  $('peak-where').textContent = P.t == null ? ''
    : 'at ' + P.t.toFixed(1) + ' s · link ' + P.link + (P.line ? ' of ' + P.line : '');
  const delivered = fpsTimes.length > 1
    ? (fpsTimes.length - 1) * 1000 / (fpsTimes[fpsTimes.length - 1] - fpsTimes[0]) : 0;
  $('fps').textContent = (s.paused ? 0 : delivered).toFixed(1);
  $('fps-server').textContent = ' / ' + (s.fps ?? 0).toFixed(0);
  $('realtime').textContent = (s.realtime ?? 0).toFixed(2) + '×';

  const pause = $('pause');
  pause.textContent = s.paused ? 'Resume' : 'Pause';
  pause.setAttribute('aria-pressed', String(s.paused));
  $('step').disabled = !s.paused;

  const L = s.limits || {};
  setSlider('speed', s.speed, L.speed);
  // Amplitude and period belong to a driven end: a scene without one has neither.
  $('amplitude-row').hidden = !s.has_period;
  $('amplitude').disabled = !s.has_period;
  if (s.has_period) setSlider('amplitude', s.amplitude_scale, L.amplitude_scale);
  // A current over time is the scene's table's: shown as it is now, not a control.
  const table = !!s.current_from_table;
  for (const id of ['current', 'current_heading']) {
    $(id).disabled = table;
    $(id).title = table ? 'The scene\'s current table sets it; shown as it is now' : '';
  }
  setSlider('current', table ? s.current_now : s.current, L.current);
  // The dial is 0 to 360 whatever the limits.
  setSlider('current_heading', table ? s.current_heading_now : s.current_heading);
  $('period-row').hidden = !s.has_period;
  $('period').disabled = !s.has_period;
  if (s.has_period) setSlider('period', s.period, L.period);
  // The vessel (the points a ship carries): its offset along x and z.
  for (const id of ['offset_x', 'offset_z']) {
    $(id.replace('_', '-') + '-row').hidden = !s.has_offset;
    $(id).disabled = !s.has_offset;
    if (s.has_offset) setSlider(id, s[id], L.offset);
  }
  // The free bodies: an extra steady force along x and z (the slider's step a hundredth of
  // its range).
  for (const id of ['force_x', 'force_z']) {
    $(id.replace('_', '-') + '-row').hidden = !s.has_force;
    $(id).disabled = !s.has_force;
    if (s.has_force && L.force) $(id).step = String((L.force[1] - L.force[0]) / 200);
    if (s.has_force) setSlider(id, s[id], L.force);
  }
  // The panel's title: what its controls move (a driven motion or the vessel that carries it,
  // a free body's force, the sea: its current and its waves).
  const parts = [(s.has_period || s.has_offset) && 'motion', s.has_force && 'force',
    'sea'].filter(Boolean);
  const title = parts.length > 1 ? parts.slice(0, -1).join(', ') + ' and ' + parts.at(-1) : parts[0];
  $('sea-title').textContent = title[0].toUpperCase() + title.slice(1);
  $('wave-height-row').hidden = !s.has_waves;
  $('wave_height').disabled = !s.has_waves;
  if (s.has_waves) setSlider('wave_height', s.wave_height, L.wave_height);
  $('wave-period-row').hidden = !s.has_waves;
  $('wave_period').disabled = !s.has_waves;
  if (s.has_waves) setSlider('wave_period', s.wave_period, L.wave_period);
  $('wave-heading-row').hidden = !s.has_waves;
  $('wave_heading').disabled = !s.has_waves;
  if (s.has_waves) setSlider('wave_heading', s.wave_heading);

  const select = $('colormap');
  const names = (s.colormaps || [s.colormap]).join();
  if (select.dataset.names !== names) {
    select.replaceChildren(...(s.colormaps || [s.colormap]).map((n) => new Option(n, n)));
    select.dataset.names = names;
  }
  if (!select.dataset.busy) select.value = s.colormap;
  const stops = COLORMAPS[s.colormap] || COLORMAPS.viridis;
  $('colorbar').style.background = `linear-gradient(90deg, ${stops.join(', ')})`;
  const R = s.range || {};
  $('range-min').textContent = kN(R.min);
  $('range-max').textContent = kN(R.max);
  const lock = $('lock-range');
  if (!lock.dataset.busy) lock.checked = !!R.locked;

  const rec = $('record');
  rec.classList.toggle('recording', !!s.recording);
  rec.setAttribute('aria-pressed', String(!!s.recording));
  $('record-label').textContent = s.recording ? 'Stop recording' : 'Record film';
  const list = $('recordings');
  const recs = s.recordings || [];
  if (list.dataset.key !== JSON.stringify(recs)) {
    list.dataset.key = JSON.stringify(recs);
    list.replaceChildren(...recs.slice().reverse().map((r) => {  // the newest first
      const li = document.createElement('li');
      const a = document.createElement('a');
      a.href = r.url; a.download = r.name; a.textContent = r.name;
      const n = document.createElement('span');
      n.className = 'dim';
      n.textContent = r.seconds != null ? r.seconds.toFixed(1) + ' s' : r.frames + ' frames';
      n.title = r.frames + ' frames' + (r.t_start != null
        ? ', t = ' + r.t_start.toFixed(1) + ' to ' + r.t_end.toFixed(1) + ' s' : '');
      li.append(a, n);
      return li;
    }));
  }
}

// Sliders marked data-log move in log10 of the value (speed, period); data-angle ones show a
// heading from 0 to 360 degrees (the server takes -360 to 360: -90 is 270).
// A slider the user is moving (data-busy) is left alone until the server has answered.
function setSlider(id, value, limits) {
  const el = $(id);
  const pos = (v) => ('log' in el.dataset ? Math.log10(v) : 'angle' in el.dataset ? turn(v) : v);
  if (limits) { el.min = pos(limits[0]); el.max = pos(limits[1]); }
  if (value == null || el.dataset.busy) return;
  el.value = pos(value);
  $(id + '-out').textContent = fmt[el.dataset.field](value);
}

// ---- controls ---------------------------------------------------------------------------
function wsOpen() { return ws && ws.readyState === WebSocket.OPEN; }

// Sends one control object; resolves to the new state, or rejects with the server's error.
async function sendControl(control) {
  let reply;
  if (wsOpen()) {
    reply = await new Promise((resolve) => {
      pending.push(resolve);
      ws.send(JSON.stringify(control));
    });
  } else {
    const r = await fetch('/control', {
      method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify(control),
    });
    const j = await r.json().catch(() => ({ error: 'HTTP ' + r.status }));
    reply = r.ok ? { ok: true, state: j } : { ok: false, error: j.error || 'HTTP ' + r.status };
  }
  if (!reply.ok) throw new Error(reply.error || 'control refused');
  return reply.state;
}

// Sends a control and shows the outcome; done() runs first, before the state is applied.
function control(obj, done = () => {}) {
  return sendControl(obj)
    .then((s) => { done(); showMessage(''); if (s) applyState(s); })
    .catch((e) => {
      done();
      showMessage(e.message, true);
      if (state) applyState(state);  // put the controls back where the server has them
    });
}

// What stopped the run or failed (a blow-up, a recording, the drawing): shown until it is
// gone from the state, not for a few seconds like a refused control.
function showAlert(s) {
  const parts = [];
  if (s.error) parts.push(['Simulation stopped', s.error]);
  if (s.record_error) parts.push(['Recording failed', s.record_error]);
  if (s.render_error) parts.push(['Drawing failed', s.render_error]);
  const box = $('alert');
  const key = JSON.stringify(parts);
  if (box.dataset.key === key) return;
  box.dataset.key = key;
  box.replaceChildren(...parts.map(([what, why]) => {
    const p = document.createElement('p');
    const b = document.createElement('b');
    b.textContent = what + ': ';
    p.append(b, why);
    return p;
  }));
  box.hidden = parts.length === 0;
}

let messageTimer = null;
function showMessage(text, isError) {
  const m = $('message');
  clearTimeout(messageTimer);
  m.hidden = !text;
  m.textContent = text;
  m.classList.toggle('error', !!isError);
  if (text) messageTimer = setTimeout(() => { m.hidden = true; }, 8000);
}

// Sliders: the label follows the thumb; the value goes out at most every 200 ms while
// dragging ('input') and once more on release ('change'). A slider being dragged or waiting
// for its answer is marked data-busy, and state updates leave it alone.
function sliderValue(el) {
  const v = Number(el.value);
  if (!('log' in el.dataset)) return v;
  const lo = Math.pow(10, Number(el.min));  // keep the ends exact despite rounding
  const hi = Math.pow(10, Number(el.max));
  return Math.min(hi, Math.max(lo, Number(Math.pow(10, v).toPrecision(3))));
}
document.querySelectorAll('input[type=range]').forEach((el) => {
  let held = false;
  let inflight = 0;
  let timer = null;
  let last = 0;
  const mark = () => { if (held || inflight) el.dataset.busy = '1'; else delete el.dataset.busy; };
  const send = () => {
    clearTimeout(timer); timer = null;
    last = performance.now();
    inflight += 1; mark();
    control({ [el.dataset.field]: sliderValue(el) }, () => { inflight -= 1; mark(); });
  };
  el.addEventListener('input', () => {
    held = true; mark();
    $(el.id + '-out').textContent = fmt[el.dataset.field](sliderValue(el));
    if (!timer) timer = setTimeout(send, Math.max(0, 200 - (performance.now() - last)));
  });
  el.addEventListener('change', () => { held = false; send(); });
});

// ---- the 3D camera ------------------------------------------------------------------------
// A scene drawn in space: a drag on its perspective view orbits the camera, the wheel zooms,
// a double click puts it back. The camera goes to the server as a control (it draws with it),
// at most one in flight: moves made meanwhile are merged into the next.
const ORBIT_DEG_PER_PX = 0.35;  // of the frame's own pixels: a drag across the view turns ~180°
const ZOOM_PER_WHEEL = 0.0015;  // per wheel delta unit (a notch of 100: ~15 %)
let camera = null;              // the camera as this page has moved it (the server clamps it)
let cameraBusy = false;
let cameraDirty = false;
let drag = null;                // {x, y} of the pointer in frame pixels while dragging

// The frame pixel under a mouse event: #frame is scaled to fit its box (object-fit: contain).
function framePoint(e) {
  if (!state || !state.width) return null;
  const r = img.getBoundingClientRect();
  const k = Math.min(r.width / state.width, r.height / state.height);
  if (!(k > 0)) return null;
  return { x: (e.clientX - r.left - (r.width - k * state.width) / 2) / k,
           y: (e.clientY - r.top - (r.height - k * state.height) / 2) / k };
}

function inSpaceView(p) {
  const v = state && state.space && state.space_view;
  return !!(p && v && p.x >= v[0] && p.x <= v[2] && p.y >= v[1] && p.y <= v[3]);
}

function sendCamera() {
  if (cameraBusy || !cameraDirty || !camera) return;
  cameraBusy = true;
  cameraDirty = false;
  control({ camera }, () => { cameraBusy = false; }).then(() => {
    if (state && state.camera && !cameraDirty) camera = { ...state.camera };
    sendCamera();  // what moved meanwhile
  });
}

function moveCamera(change) {
  if (!state || !state.space) return;
  if (!camera) camera = { ...state.camera };
  change(camera);
  camera.elevation = Math.max(-89, Math.min(89, camera.elevation));
  camera.zoom = Math.max(0.2, Math.min(20, camera.zoom));
  cameraDirty = true;
  sendCamera();
}

img.draggable = false;
img.addEventListener('pointerdown', (e) => {
  const p = framePoint(e);
  if (e.button !== 0 || !inSpaceView(p)) return;
  e.preventDefault();
  img.setPointerCapture(e.pointerId);
  drag = p;
  body.dataset.orbiting = '1';
});
img.addEventListener('pointermove', (e) => {
  const p = framePoint(e);
  img.classList.toggle('orbit', !!drag || inSpaceView(p));
  if (!drag || !p) return;
  const dx = p.x - drag.x, dy = p.y - drag.y;
  drag = p;
  // Dragging right carries the scene round to the right: the eye goes the other way.
  moveCamera((c) => { c.azimuth -= dx * ORBIT_DEG_PER_PX; c.elevation += dy * ORBIT_DEG_PER_PX; });
});
const endDrag = () => { drag = null; delete body.dataset.orbiting; };
img.addEventListener('pointerup', endDrag);
img.addEventListener('pointercancel', endDrag);
img.addEventListener('wheel', (e) => {
  if (!inSpaceView(framePoint(e))) return;
  e.preventDefault();
  const delta = e.deltaMode === 1 ? 40 * e.deltaY : e.deltaY;  // lines to pixels
  moveCamera((c) => { c.zoom *= Math.exp(-delta * ZOOM_PER_WHEEL); });
}, { passive: false });
img.addEventListener('dblclick', (e) => {
  if (!inSpaceView(framePoint(e))) return;
  e.preventDefault();
  camera = null;
  cameraDirty = false;
  control({ camera: 'reset' });
});

function togglePause() { if (state) control({ pause: !state.paused }); }
function step() { if (state && state.paused) control({ step: true }); }
function restart() { control({ restart: true }); }

$('pause').addEventListener('click', togglePause);
$('step').addEventListener('click', step);
$('restart').addEventListener('click', restart);
for (const [id, make] of [['colormap', (el) => ({ colormap: el.value })],
                          ['lock-range', (el) => ({ lock_range: el.checked })]]) {
  const el = $(id);
  el.addEventListener('change', () => {
    el.dataset.busy = '1';
    control(make(el), () => delete el.dataset.busy);
  });
}
$('record').addEventListener('click', () => control({ record: !(state && state.recording) }));
$('reset-range').addEventListener('click', () => control({ reset_range: true }));

document.addEventListener('keydown', (e) => {
  const tag = e.target.tagName;
  const typing = tag === 'TEXTAREA' || tag === 'SELECT' || e.target.isContentEditable ||
    (tag === 'INPUT' && !['range', 'checkbox', 'button'].includes(e.target.type));
  if (typing || e.ctrlKey || e.metaKey || e.altKey || e.repeat) return;
  if (e.key === ' ') { e.preventDefault(); togglePause(); }  // also stops a focused button's click
  else if (e.key === 'r' || e.key === 'R') { e.preventDefault(); restart(); }
  else if (e.key === '.') { e.preventDefault(); step(); }
});

// ---- connection -------------------------------------------------------------------------
function setStatus(kind, text) {
  const s = $('status');
  s.dataset.state = kind;
  s.textContent = text;
  body.dataset.transport = { live: 'websocket', polling: 'polling', retrying: 'polling' }[kind] || 'none';
}

function connect() {
  if (!('WebSocket' in window)) { startPolling(); return; }
  ws = new WebSocket((location.protocol === 'https:' ? 'wss://' : 'ws://') + location.host + '/ws');
  ws.binaryType = 'arraybuffer';
  ws.onopen = () => {
    wsOpened = true;
    retryMs = 500;
    stopPolling();
    setStatus('live', 'live');
  };
  ws.onmessage = (e) => {
    if (typeof e.data !== 'string') { onBinary(e.data); return; }
    let msg;
    try { msg = JSON.parse(e.data); } catch { return; }
    if (msg.type === 'reply') { const resolve = pending.shift(); if (resolve) resolve(msg); }
    else if (msg.type === 'state') applyState(msg);
  };
  ws.onclose = () => {
    ws = null;
    pending.splice(0).forEach((resolve) => resolve({ ok: false, error: 'connection lost' }));
    startPolling();  // keeps the page alive meanwhile, and is all there is without /ws
    if (wsOpened && !pollFailures) setStatus('retrying', 'reconnecting…');
    setTimeout(connect, retryMs);
    retryMs = Math.min(retryMs * 2, 8000);
  };
}

// Returns the delay before the next poll: longer and longer while the server is unreachable.
let pollFailures = 0;
async function pollOnce() {
  try {
    const s = await (await fetch('/state', { cache: 'no-store' })).json();
    applyState(s);
    if (s.frame + ':' + s.seq !== lastKey) {
      const r = await fetch('/frame.jpg?n=' + s.frame, { cache: 'no-store' });
      if (r.ok) showFrame(await r.blob(), s.frame, s.t, s.seq);
    }
    if (!wsOpen()) setStatus(wsOpened ? 'retrying' : 'polling', wsOpened ? 'reconnecting…' : 'polling');
    pollFailures = 0;
    return POLL_MS;
  } catch {
    setStatus('offline', 'server unreachable');
    $('placeholder-text').textContent = 'Connection lost: retrying…';
    $('fps').textContent = '–';
    pollFailures += 1;
    return Math.min(8000, POLL_MS * 2 ** pollFailures);
  }
}

function startPolling() {
  if (pollTimer) return;
  const loop = async () => {
    const delay = await pollOnce();
    if (pollTimer) pollTimer = setTimeout(loop, delay);
  };
  pollTimer = setTimeout(loop, 0);
}

function stopPolling() { clearTimeout(pollTimer); pollTimer = null; }

window.cablefilm = { sendControl, control, get state() { return state; } };  // for tests and the console
// Opened with the access token in its address (a server bound beyond loopback): the server has
// set it as a cookie; out of the address bar it is not shared with a screenshot or a link.
if (new URLSearchParams(location.search).has('token')) history.replaceState(null, '', location.pathname);
connect();
