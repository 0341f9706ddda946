// The control page: polls GET /api/state a few times a second, draws the wall from it and
// reloads a display's picture when the run has published new ones. The buttons POST to
// /api/...; the run takes each request at its next frame and the state then says so.
'use strict';

const token = new URLSearchParams(location.search).get('token') || '';
const POLL_MS = 250;
const $ = (id) => document.getElementById(id);
// One colour per swap group and per pipeserver, the same on every page load.
const palette = ['#4e9af1', '#f1a14e', '#5cc97b', '#e85d75', '#b07cf0', '#e3d35a', '#4ed6d0',
                 '#f07cc8'];
const colour = (i) => palette[((i % palette.length) + palette.length) % palette.length];

let wallKey = '';        // the displays last drawn; the wall is rebuilt when they change
let picturesShown = -1;  // the pictures_version whose pictures are on the page
let state = null;

function api(path, params = {}) {
  const q = new URLSearchParams(params);
  if (token) q.set('token', token);
  return `${path}?${q}`;
}

async function post(action, params = {}) {
  const res = await fetch(api(`/api/${action}`, params), { method: 'POST' });
  if (!res.ok) showError(`${action}: ${(await res.json()).error || res.status}`);
}

function showError(text) {
  $('error').textContent = text;
  $('error').hidden = !text;
}

// Every Nth pixel, so a picture is about as large as it is shown (never below 1:1).
function scaleFor(display, shownWidth) {
  return Math.max(1, Math.min(64, Math.floor(display.width / Math.max(1, shownWidth))));
}

function buildWall(s) {
  const wall = $('wall');
  wall.replaceChildren();
  const canvas = s.wall.canvas;
  wall.style.aspectRatio = `${canvas.width} / ${canvas.height}`;
  for (const d of s.displays) {
    const box = document.createElement('div');
    box.className = 'display';
    box.style.left = `${(100 * d.x) / canvas.width}%`;
    box.style.top = `${(100 * d.y) / canvas.height}%`;
    box.style.width = `${(100 * d.width) / canvas.width}%`;
    box.style.height = `${(100 * d.height) / canvas.height}%`;
    box.style.setProperty('--group', colour(d.swap_group));
    const hung = [d.rotation ? `turned ${d.rotation}` : '', d.flip && d.flip !== 'none' ? `flipped ${d.flip}` : '']
      .filter(Boolean)
      .join(', ');
    box.title = `display ${d.id}: ${d.width}x${d.height} at (${d.x}, ${d.y})${hung ? ` (${hung})` : ''}, swap group ${d.swap_group}`;
    const img = document.createElement('img');
    img.dataset.id = d.id;
    img.alt = `display ${d.id}`;
    const label = document.createElement('span');
    label.className = 'label';
    label.textContent = `display ${d.id}`;
    box.append(img, label);
    box.addEventListener('click', () => window.open(api(`/api/display/${d.id}.png`), '_blank'));
    wall.append(box);
  }
  const svg = document.createElementNS('http://www.w3.org/2000/svg', 'svg');
  svg.id = 'tiles';
  svg.setAttribute('viewBox', `0 0 ${canvas.width} ${canvas.height}`);
  svg.setAttribute('preserveAspectRatio', 'none');
  const windows = svg.cloneNode();
  windows.id = 'windows';
  wall.append(svg, windows);
  picturesShown = -1;
}

function drawTiles(s) {
  const svg = $('tiles');
  svg.replaceChildren();
  if (!$('show-tiles').checked) return;
  for (const t of s.tiles) {
    const r = document.createElementNS('http://www.w3.org/2000/svg', 'rect');
    for (const k of ['x', 'y', 'width', 'height']) r.setAttribute(k, t[k]);
    r.setAttribute('stroke', colour(t.pipeserver));
    const title = document.createElementNS('http://www.w3.org/2000/svg', 'title');
    title.textContent = `pipeserver ${t.pipeserver}: ${t.width}x${t.height} at (${t.x}, ${t.y})`;
    r.append(title);
    svg.append(r);
  }
}

// A point of the page in canvas pixels.
function canvasPoint(e) {
  const box = $('windows').getBoundingClientRect();
  const canvas = state.wall.canvas;
  return { x: ((e.clientX - box.left) * canvas.width) / box.width,
           y: ((e.clientY - box.top) * canvas.height) / box.height };
}

// A session's windows as the displays show them. Where the run can move them, the gestures of
// window_gestures.js move, resize and raise them (POST /api/window, taken from the run's next
// frame).
let windowsKey = '';  // what the window outlines show: redrawn only when that changes

function drawWindows(s) {
  const svg = $('windows');
  if (windowGestureActive()) return;  // a held outline follows the gesture, not the state
  const key = JSON.stringify([s.windows, s.live && !s.ended, $('show-windows').checked, wallKey]);
  if (key === windowsKey) return;
  windowsKey = key;
  svg.replaceChildren();
  if (!$('show-windows').checked) return;
  for (const w of s.windows.shown) {
    const g = document.createElementNS('http://www.w3.org/2000/svg', 'g');
    g.classList.add('window');
    g.classList.toggle('movable', s.windows.movable && s.live && !s.ended);
    g.dataset.id = w.id;
    const r = document.createElementNS('http://www.w3.org/2000/svg', 'rect');
    for (const k of ['x', 'y', 'width', 'height']) r.setAttribute(k, w[k]);
    const label = document.createElementNS('http://www.w3.org/2000/svg', 'text');
    label.setAttribute('x', w.x + 8);
    label.setAttribute('y', w.y + 24);
    label.textContent = `${w.id}: ${w.source}`;
    const title = document.createElementNS('http://www.w3.org/2000/svg', 'title');
    title.textContent = `window ${w.id} (${w.source}): ${w.width}x${w.height} at (${w.x}, ${w.y})` +
                        (s.windows.movable ? '; drag to move, wheel or pinch to resize, ' +
                                             'double-click or tap to raise' : '');
    g.append(r, label, title);
    if (g.classList.contains('movable')) listenForGestures(g, w);
    svg.append(g);
  }
}

// A display's picture is replaced only once the new one has loaded: no flicker, and at most one
// request per display in flight.
function reloadPictures(s) {
  if (s.pictures_version === picturesShown) return;
  picturesShown = s.pictures_version;
  for (const img of document.querySelectorAll('#wall img')) {
    if (img.dataset.loading) continue;
    const d = s.displays.find((x) => String(x.id) === img.dataset.id);
    const scale = scaleFor(d, img.parentElement.clientWidth * devicePixelRatio);
    const next = new Image();
    img.dataset.loading = '1';
    next.onload = () => {
      img.src = next.src;
      img.dataset.scale = scale;
      img.dataset.version = s.pictures_version;
      delete img.dataset.loading;
    };
    next.onerror = () => delete img.dataset.loading;
    next.src = api(`/api/display/${d.id}.png`, { scale, v: s.pictures_version });
  }
}

function chart(p) {
  const c = document.createElement('canvas');
  c.className = 'chart';
  c.width = 180;
  c.height = 36;
  const g = c.getContext('2d');
  const values = p.recent.flatMap((f) => [f.render_ms, f.ready_wait_ms]);
  const top = Math.max(1, ...values);
  const line = (key, stroke) => {
    g.strokeStyle = stroke;
    g.beginPath();
    p.recent.forEach((f, i) => {
      const x = (i / Math.max(1, p.recent.length - 1)) * (c.width - 1);
      const y = c.height - 1 - (f[key] / top) * (c.height - 2);
      if (i === 0) g.moveTo(x, y); else g.lineTo(x, y);
    });
    g.stroke();
  };
  line('render_ms', colour(p.index));
  line('ready_wait_ms', '#888');
  c.title = `render (colour) and READY wait (grey), ms; top ${top.toFixed(1)} ms`;
  return c;
}

function drawPipeservers(s) {
  const body = $('pipeservers').tBodies[0];
  body.replaceChildren();
  for (const p of s.pipeservers) {
    const last = p.recent[p.recent.length - 1];
    const row = body.insertRow();
    if (p.lost) row.className = 'lost';
    const cells = [p.index, p.place + (p.lost ? ' (lost)' : ''),
                   last ? last.render_ms.toFixed(2) : '-', last ? last.ready_wait_ms.toFixed(2) : '-',
                   last ? last.sync_retries : '-'];
    cells.forEach((text, i) => {
      const cell = row.insertCell();
      cell.textContent = text;
      if (i === 1) cell.className = 'place';
      if (i === 1 && p.renderer) cell.title = `renderer: ${p.renderer}`;
    });
    const c = row.insertCell();
    c.append(chart(p));
    if (p.back_channel) c.title = `back-channel: ${p.back_channel}`;
  }
}

function drawEvents(s) {
  const list = $('events');
  list.replaceChildren();
  for (const e of s.events) {
    const li = document.createElement('li');
    li.textContent = (e.frame >= 0 ? `frame ${e.frame}: ` : '') + e.text;
    list.append(li);
  }
  list.scrollTop = list.scrollHeight;
  $('summary').hidden = !s.summary;
  $('summary').textContent = s.summary;
  const pictures = $('pictures');
  pictures.replaceChildren();
  for (const name of s.pictures) {
    const a = document.createElement('a');
    a.href = api(`/api/picture/${name}`);
    a.target = '_blank';
    a.textContent = name;
    pictures.append(a);
  }
}

function drawStatus(s) {
  $('wall-name').textContent = `l2wall: ${s.wall.name}`;
  $('frame').textContent = s.frame;
  $('frames-planned').textContent = s.frames_planned ? ` / ${s.frames_planned}` : '';
  $('fps').textContent = s.fps.toFixed(1);
  $('latency').textContent = s.latency_frames >= 0 ? `${s.latency_frames} frame(s)` : 'not measured';
  $('limited-by').textContent = s.limited_by;
  const badge = $('run-state');
  const fault = s.ended.includes('fault');
  badge.textContent = s.ended ? (fault ? 'ended in a fault' : 'ended') : s.paused ? 'paused' : 'running';
  badge.className = `badge${s.ended ? (fault ? ' fault ended' : ' ended') : s.paused ? ' paused' : ''}`;
  const steerable = s.live && !s.ended;
  $('pause').disabled = !steerable || s.paused;
  $('resume').disabled = !steerable || !s.paused;
  $('save').disabled = !steerable || s.frame < 0;
  $('stop').disabled = !steerable || !s.stoppable;
  $('stop').title = s.stoppable ? 'End the run after this frame, as q does'
                                : 'Under --mpi the pipeserver ranks cannot be ended early: Ctrl-C on mpirun ends the run';
  $('windows-control').hidden = !s.windows.shown.length;
  const modes = $('balance-mode');
  $('balance-control').hidden = !s.balance.mode;
  if (s.balance.mode && modes.options.length !== s.balance.modes.length) {
    modes.replaceChildren(...s.balance.modes.map((m) => new Option(m, m)));
  }
  if (s.balance.mode && document.activeElement !== modes) modes.value = s.balance.mode;
}

function draw(s) {
  const key = JSON.stringify([s.wall, s.displays]);
  if (key !== wallKey) {
    wallKey = key;
    buildWall(s);
  }
  drawStatus(s);
  drawTiles(s);
  drawWindows(s);
  reloadPictures(s);
  drawPipeservers(s);
  drawEvents(s);
  if (typeof drawShares === 'function') drawShares(s);  // share_screen.js, loaded after
}

async function poll() {
  try {
    const res = await fetch(api('/api/state'), { cache: 'no-store' });
    if (res.status === 403) {
      showError('This page needs the run\'s token: open the address l2wall printed.');
    } else if (!res.ok) {
      // Busy (too many connections, 503): said, and asked again; the state shown stays.
      const why = (await res.json().catch(() => ({}))).error || res.statusText;
      showError(`l2wall answered ${res.status} (${why}): asking again`);
    } else {
      state = await res.json();
      showError('');
      draw(state);
      if (state.ended && state.live) return;  // the run is over: nothing will change
    }
  } catch (e) {
    // The run ended (its server with it) or the network dropped: say so, keep what was shown.
    if (state) {
      $('run-state').textContent = state.ended ? 'ended' : 'not reachable (run ended?)';
      $('run-state').className = 'badge ended';
      return;
    }
    showError(`cannot reach l2wall: ${e}`);
  }
  setTimeout(poll, POLL_MS);
}

$('pause').addEventListener('click', () => post('pause'));
$('resume').addEventListener('click', () => post('resume'));
$('save').addEventListener('click', () => post('save'));
$('stop').addEventListener('click', () => post('stop'));
$('balance-mode').addEventListener('change', (e) => post('balance', { mode: e.target.value }));
$('show-tiles').addEventListener('change', () => state && drawTiles(state));
$('show-windows').addEventListener('change', () => state && drawWindows(state));
poll();
