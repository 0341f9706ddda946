// Sharing a screen into a session run (control_page/README.md): the browser's capture
// (getDisplayMedia) drawn to a canvas of a fixed size and POSTed to /api/share/frame as JPEG,
// one frame in flight: the next is drawn only once the run answered the last, so a browser
// faster than the wall sends fewer frames instead of queueing them. The run opens the share's
// window (POST /api/share, centred, or where the Share button is dropped on the wall); the
// browser's own stop, or Stop sharing, closes it (POST /api/window?action=close).
// Uses app.js's $, api, post and canvasPoint (window_gestures.js), loaded with it.
'use strict';

const FRAME_GAP_MS = 30;  // at most about 30 frames a second, fewer as the run answers
const MAX_SIDE = { width: 3840, height: 2160 };  // what the run takes (kMaxShareWidth, ...)
const share = { window: -1, stream: null, sent: 0, said: '' };

function shareSays(text) {
  share.said = text;
  $('share-state').textContent = text;
}

// Where to show it: a canvas point, or null for the canvas's centre.
async function startShare(at) {
  if (share.stream) return;
  let stream;
  try {
    stream = await navigator.mediaDevices.getDisplayMedia({ video: true, audio: false });
  } catch (e) {
    return shareSays(`not shared: ${e.message}`);
  }
  const video = document.createElement('video');
  video.muted = true;
  video.srcObject = stream;
  await video.play();
  const scale = Math.min(1, MAX_SIDE.width / video.videoWidth, MAX_SIDE.height / video.videoHeight);
  const size = { width: Math.max(1, Math.round(video.videoWidth * scale)),
                 height: Math.max(1, Math.round(video.videoHeight * scale)) };
  const params = { ...size, name: $('share-name').value.trim() || 'browser' };
  if (at) Object.assign(params, { x: Math.round(at.x), y: Math.round(at.y) });
  const res = await fetch(api('/api/share', params), { method: 'POST' });
  const body = await res.json().catch(() => ({}));
  if (!res.ok) {
    stream.getTracks().forEach((t) => t.stop());
    return shareSays(body.error || `not shared: ${res.status}`);
  }
  // "sharing NAME as window 5 (WxH) at ...": the last such words, whatever the name says.
  share.window = Number([...body.done.matchAll(/ as window (\d+) \(/g)].at(-1)[1]);
  share.stream = stream;
  share.sent = 0;
  shareSays(body.done);
  stream.getVideoTracks()[0].addEventListener('ended', stopShare);
  const canvas = document.createElement('canvas');
  Object.assign(canvas, size);
  sendFrames(video, canvas, stream);
}

async function sendFrames(video, canvas, stream) {
  const g = canvas.getContext('2d');
  while (share.stream === stream) {
    g.drawImage(video, 0, 0, canvas.width, canvas.height);
    const jpeg = await new Promise((done) => canvas.toBlob(done, 'image/jpeg', 0.85));
    let res = null;
    try {
      res = await fetch(api('/api/share/frame', { window: share.window }),
                        { method: 'POST', body: jpeg, headers: { 'Content-Type': 'image/jpeg' } });
    } catch (e) {
      shareSays(`frame not sent (${e.message}): trying again`);
    }
    if (res && (res.status === 404 || res.status === 409)) {
      // The window was closed on the wall, or the run ended: the capture stops too.
      shareSays((await res.json().catch(() => ({}))).error || 'the share ended');
      stream.getTracks().forEach((t) => t.stop());
      if (share.stream === stream) share.stream = null;
      return;
    }
    if (res && !res.ok) shareSays((await res.json().catch(() => ({}))).error || `${res.status}`);
    if (res && res.ok) share.sent += 1;
    await new Promise((done) => setTimeout(done, res ? FRAME_GAP_MS : 500));
  }
}

async function stopShare() {
  const stream = share.stream;
  if (!stream) return;
  share.stream = null;
  stream.getTracks().forEach((t) => t.stop());
  shareSays(`stopped sharing window ${share.window}`);
  await post('window', { action: 'close', id: share.window });
}

// The shares the run shows, under the buttons: counts, and a share that stalled.
function drawShares(s) {
  const slots = (s.shares && s.shares.slots) || 0;
  $('share-control').hidden = !slots || !s.live;
  $('share-start').disabled = !!share.stream || !!s.ended;
  $('share-stop').disabled = !share.stream;
  const list = $('shares');
  list.replaceChildren();
  for (const x of (s.shares && s.shares.shown) || []) {
    const li = document.createElement('li');
    const since = x.seconds_since_frame;
    const stalled = since > 2 ? ` · stalled: no frame for ${since.toFixed(0)} s, the wall keeps the last` : '';
    li.textContent = `window ${x.window} (${x.name}, ${x.width}x${x.height}): ${x.received} received, ` +
                     `${x.shown} shown, ${x.dropped} dropped, ${x.refused} refused${stalled}`;
    li.className = stalled ? 'stalled' : '';
    list.append(li);
  }
}

$('share-start').addEventListener('click', () => startShare(null));
$('share-stop').addEventListener('click', stopShare);
// The Share button dropped on the wall: the window is centred where it was dropped.
$('share-start').addEventListener('dragstart', (e) => e.dataTransfer.setData('text/plain', 'share'));
$('wall').addEventListener('dragover', (e) => e.preventDefault());
$('wall').addEventListener('drop', (e) => {
  e.preventDefault();
  if (e.dataTransfer.getData('text/plain') === 'share') startShare(canvasPoint(e));
});
