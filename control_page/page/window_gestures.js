// A session's windows moved on the page's wall view with a mouse or a touch screen, as TUIO moves
// them on the wall (touch/include/touch/gestures.hpp): one pointer drags a window, two fingers
// pinch it, the wheel resizes it about the pointer, a tap (or a double click) raises it. It owns
// the gestures under way and the outline each shows; app.js draws the outlines and sends what
// a gesture ends in (POST /api/window), once per gesture, so the run takes one command for it.
'use strict';

// A session's limits (tilelayout/session_file.hpp: kMaxWindowSide, kWindowReach): the page
// keeps a resize within them, as the touch gestures do, rather than have the run refuse it.
const WINDOW_MAX_SIDE = 16384;
const WINDOW_REACH = 16384;
// A wheel's resize is sent once the wheel has rested this long: a spin is one command.
const WHEEL_REST_MS = 300;
// Pixels of wheel travel (a line counts as 40) that scale a window by e: a notch of 100, about 1.2x.
const WHEEL_PIXELS_PER_E = 500;

// A gesture per window held, by window id: its window `w` as the state showed it, `anchor` (the
// box it goes on from when its pointers change) with those pointers there, `box` now.
const holds = new Map();

function windowGestureActive() {
  return holds.size > 0;
}

// The scale `s` kept within the sides a window may have, its shape kept.
function withinSides(s, box) {
  const least = Math.max(1 / box.width, 1 / box.height);
  const most = Math.min(WINDOW_MAX_SIDE / box.width, WINDOW_MAX_SIDE / box.height);
  return Math.max(least, Math.min(s, most));
}

// `box` scaled by `s` about the canvas point `c0`, which then lies at `c`.
function scaledAbout(box, s, c0, c) {
  return { x: c.x - (c0.x - box.x) * s, y: c.y - (c0.y - box.y) * s, width: box.width * s,
           height: box.height * s };
}

// The whole-pixel window command's numbers for `box`, within the session's limits.
function windowPlace(box) {
  const whole = (v, lo, hi) => Math.max(lo, Math.min(hi, Math.round(v)));
  return { x: whole(box.x, -WINDOW_REACH, WINDOW_REACH), y: whole(box.y, -WINDOW_REACH, WINDOW_REACH),
           w: whole(box.width, 1, WINDOW_MAX_SIDE), h: whole(box.height, 1, WINDOW_MAX_SIDE) };
}

// The outline drawn at `box` instead of where the state has the window.
function showBox(h) {
  const s = h.box.width / h.w.width;
  h.g.setAttribute('transform',
                   `matrix(${s} 0 0 ${s} ${h.box.x - s * h.w.x} ${h.box.y - s * h.w.y})`);
}

// How far a pointer may wander and still tap: 1% of the canvas's longer side, as TUIO's taps.
function slop() {
  return Math.max(state.wall.canvas.width, state.wall.canvas.height) / 100;
}

function holdOf(g, w) {
  let h = holds.get(w.id);
  if (!h) {
    h = { g, w, pointers: new Map(), box: { x: w.x, y: w.y, width: w.width, height: w.height },
          moved: false, pinched: false, wheel: 0, tap: true };
    holds.set(w.id, h);
  }
  return h;
}

// The box and the (first two) pointers now: what the gesture goes on from.
function anchor(h) {
  h.anchor = { ...h.box };
  h.anchorAt = [...h.pointers.values()].slice(0, 2).map((p) => ({ ...p.at }));
}

function pointerDown(e, g, w) {
  e.preventDefault();
  const h = holdOf(g, w);
  if (h.pointers.size >= 2) return;  // a third finger on a window is ignored
  g.setPointerCapture(e.pointerId);
  const at = canvasPoint(e);
  h.pointers.set(e.pointerId, { at, landed: at, mouse: e.pointerType === 'mouse' });
  if (h.pointers.size === 2) h.tap = false;
  anchor(h);
}

function pointerMove(e, w) {
  const h = holds.get(w.id);
  const p = h && h.pointers.get(e.pointerId);
  if (!p) return;
  p.at = canvasPoint(e);
  const [a0, a1] = h.anchorAt;
  if (h.pointers.size === 1) {
    if (!h.moved && Math.hypot(p.at.x - p.landed.x, p.at.y - p.landed.y) <= slop()) return;
    h.moved = true;
    h.tap = false;
    h.box = { ...h.anchor, x: h.anchor.x + p.at.x - a0.x, y: h.anchor.y + p.at.y - a0.y };
  } else {
    const [p0, p1] = [...h.pointers.values()].map((q) => q.at);
    const was = Math.hypot(a1.x - a0.x, a1.y - a0.y);
    const s = withinSides(was >= 1 ? Math.hypot(p1.x - p0.x, p1.y - p0.y) / was : 1, h.anchor);
    const mid = (u, v) => ({ x: (u.x + v.x) / 2, y: (u.y + v.y) / 2 });
    h.box = scaledAbout(h.anchor, s, mid(a0, a1), mid(p0, p1));
    h.moved = true;
  }
  showBox(h);
}

// A lifted pointer: the other of a pinch drags on from where the window is; the last ends the
// gesture, with the window's new place, or a raise for a tap of a finger or a pen.
function pointerUp(e, w) {
  const h = holds.get(w.id);
  const p = h && h.pointers.get(e.pointerId);
  if (!p) return;
  h.pointers.delete(e.pointerId);
  if (h.pointers.size) return anchor(h);
  if (h.tap && !p.mouse && e.type === 'pointerup') {
    holds.delete(w.id);
    h.g.removeAttribute('transform');
    return post('window', { action: 'raise', id: w.id });
  }
  return endGesture(h);
}

// The wheel over a window resizes it about the pointer; a spin is sent once it rests.
function wheel(e, g, w) {
  e.preventDefault();
  const h = holdOf(g, w);
  if (h.pointers.size) return;  // a window held by a pointer follows that pointer
  h.tap = false;
  const pixels = e.deltaY * (e.deltaMode === WheelEvent.DOM_DELTA_LINE ? 40 : 1);
  const total = h.box.width / w.width;
  const s = withinSides(total * Math.exp(-pixels / WHEEL_PIXELS_PER_E), w) / total;
  const at = canvasPoint(e);
  h.box = scaledAbout(h.box, s, at, at);
  h.moved = true;
  showBox(h);
  clearTimeout(h.wheel);
  h.wheel = setTimeout(() => endGesture(h), WHEEL_REST_MS);
}

// The window's new place, once, to the run; the outline is drawn again from the state.
async function endGesture(h) {
  clearTimeout(h.wheel);  // a wheel's spin that a pointer went on with ends with the pointer
  if (holds.get(h.w.id) !== h) return;
  holds.delete(h.w.id);
  if (!h.moved) return h.g.removeAttribute('transform');
  windowsKey = '';
  const to = windowPlace(h.box);
  if (to.x === h.w.x && to.y === h.w.y && to.w === h.w.width && to.h === h.w.height) {
    h.g.removeAttribute('transform');
    return;
  }
  await post('window', { action: 'move', id: h.w.id, ...to });
  if (state && !windowGestureActive()) drawWindows(state);
}

// The gestures on one window's outline.
function listenForGestures(g, w) {
  g.addEventListener('pointerdown', (e) => pointerDown(e, g, w));
  g.addEventListener('pointermove', (e) => pointerMove(e, w));
  g.addEventListener('pointerup', (e) => pointerUp(e, w));
  g.addEventListener('pointercancel', (e) => pointerUp(e, w));
  g.addEventListener('wheel', (e) => wheel(e, g, w), { passive: false });
  g.addEventListener('dblclick', () => post('window', { action: 'raise', id: w.id }));
}
