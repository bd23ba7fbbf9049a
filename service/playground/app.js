// The playground: control points edited with the mouse (or a finger), everything else
// asked of the service. State changes schedule one round of requests at a time; when
// the state changed again while a round was out, one more round follows with the
// newest state, so dragging never floods the service and the last answer always
// matches what is on screen.

import {ApiError, apiToken, setApiToken} from './api.js';
import {drawBernstein} from './bernstein.js';
import {drawCanonicalMap} from './canonical.js';
import {computeRound, usedCurves} from './compute.js';
import {drawScene, kColors, kPointNames, formatNumber} from './draw.js';
import {kExamples} from './examples.js';
import {markAt, pointAt} from './hit.js';
import {NearestTracker} from './nearest.js';
import {renderErrors, renderIntersections, renderLoops, renderTypes, renderValues} from './panels.js';
import {View} from './view.js';

const $ = (id) => document.getElementById(id);

const state = {
  curves: [{name: 'A', points: []}, {name: 'B', points: []}],
  second: false,
  active: 0,
  t0: 0.5,
  mode: 'add',
  show: {
    polygon: true, curve: true, points: true, labels: true, polar: true, polarPoints: true,
    loops: true, classify: true, intersections: true, box: true, frame: true, nearest: true,
  },
};


let answers = null;  // the last round's answers (for `answered` below)
let errors = [];
let answeredKey = null;  // request key of the state those answers are for
let inFlight = false;
let hover = null;  // {curve, index} of the control point under the cursor
let hoverMark = -1;  // index of the intersection under the cursor
let drag = null;  // {curve, index, pointerId}

const canvas = $('scene');
const view = new View(canvas);
const nearest = new NearestTracker(() => {
  renderScene();
  renderValues($('values'), state, answers, currentNearest());
});

/** The nearest-point answer for the edited curve as it is now, or null. */
function currentNearest() {
  return state.show.nearest ? nearest.current(state.curves[state.active].points) : null;
}

/** Asks for the edited curve's point nearest to canvas position (sx, sy). */
function askNearest(sx, sy) {
  const points = state.curves[state.active].points;
  if (!state.show.nearest || points.length < 2) return;
  nearest.request(points, view.toWorld(sx, sy));
}

/** What the requests depend on: nothing else triggers a round. */
function requestKey() {
  return JSON.stringify([state.curves.map((c) => c.points), state.second, state.active, state.t0]);
}

function isIdle() {
  return !inFlight && answeredKey === requestKey();
}

function updateStatus() {
  const idle = isIdle();
  document.documentElement.dataset.idle = String(idle);
  const status = $('status');
  status.classList.toggle('busy', !idle);
  status.textContent = idle ? (errors.length ? `${errors.length} request${errors.length > 1 ? 's' : ''} failed` : 'Up to date')
                            : 'Asking the service…';
}

async function schedule() {
  if (inFlight) return;
  inFlight = true;
  updateStatus();
  while (answeredKey !== requestKey()) {
    const key = requestKey();
    const snapshot = structuredClone({curves: state.curves, second: state.second, active: state.active, t0: state.t0});
    try {
      const round = await computeRound(snapshot);
      answers = round.answers;
      errors = round.errors;
    } catch (e) {
      // An answer of an unexpected shape: say so instead of stalling.
      answers = null;
      errors = [{what: 'drawing the answers', error: new ApiError('(page)', 0, {title: 'Page error', detail: String(e)})}];
    }
    answeredKey = key;
    renderPanels();
    renderScene();
  }
  inFlight = false;
  updateStatus();
}

function changed() {
  renderScene();
  renderPanels();
  schedule();
}

function renderScene() {
  $('hint').hidden = state.curves[0].points.length > 0 || state.curves[1].points.length > 0;
  drawScene(view, state, answers, hover, hoverMark, currentNearest());
  const curveIndex = hover ? hover.curve : state.active;
  const n = state.curves[curveIndex].points.length - 1;
  $('bernstein-caption').textContent = n >= 1 ? `degree ${n}, curve ${state.curves[curveIndex].name}` : '';
  drawBernstein($('bernstein'), n, hover ? hover.index : -1, kColors.curves[curveIndex], state.t0);
  updateStatus();
}

function renderPanels() {
  renderValues($('values'), state, answers, currentNearest());
  renderTypes($('types'), state, answers);
  renderIntersections($('intersections'), state, answers);
  renderLoops($('loops'), state, answers);
  renderErrors($('errors'), errors);
  const section = $('classify-section');
  section.hidden = !state.show.classify;
  if (state.show.classify) {
    const marks = usedCurves(state).map((i) => ({
      label: kPointNames[i], color: kColors.curves[i], point: answers?.curves[i]?.classify?.canonical_point ?? null,
    }));
    drawCanonicalMap($('canonical'), marks);
  }
}

// --- pointer editing ------------------------------------------------------------

function localPosition(event) {
  const rect = canvas.getBoundingClientRect();
  return [event.clientX - rect.left, event.clientY - rect.top];
}

const hitRadius = (event) => (event.pointerType === 'mouse' ? 10 : 20);

function markListItems() {
  for (const li of $('intersections').querySelectorAll('li[data-index]')) {
    li.classList.toggle('active', Number(li.dataset.index) === hoverMark);
  }
}

function showTooltip(sx, sy) {
  const tooltip = $('tooltip');
  markListItems();
  if (hoverMark < 0) {
    tooltip.hidden = true;
    return;
  }
  const hit = answers.intersections.intersections[hoverMark];
  tooltip.textContent = `${hit.kind} intersection\nt = ${formatNumber(hit.t)}, s = ${formatNumber(hit.s)}\n` +
      `at (${formatNumber(hit.point[0])}, ${formatNumber(hit.point[1])})`;
  tooltip.dataset.kind = hit.kind;
  tooltip.hidden = false;
  tooltip.style.left = `${Math.min(sx, view.cssWidth - 190)}px`;
  tooltip.style.top = `${sy}px`;
}

// Pointing at an intersection in the list marks it on the canvas too.
$('intersections').addEventListener('pointerover', (event) => {
  const li = event.target.closest('li[data-index]');
  hoverMark = li ? Number(li.dataset.index) : -1;
  markListItems();
  renderScene();
});
$('intersections').addEventListener('pointerleave', () => {
  hoverMark = -1;
  markListItems();
  renderScene();
});

function updateHover(event) {
  const [sx, sy] = localPosition(event);
  hover = pointAt(state, view, sx, sy, hitRadius(event));
  hoverMark = hover ? -1 : markAt(state, view, answers, sx, sy, hitRadius(event));
  canvas.classList.toggle('over-point', hover !== null && state.mode !== 'add');
  showTooltip(sx, sy);
}

canvas.addEventListener('pointermove', (event) => {
  if (drag && event.pointerId === drag.pointerId) {
    const p = view.snappedWorld(...localPosition(event));
    const points = state.curves[drag.curve].points;
    const old = points[drag.index];
    if (old[0] !== p[0] || old[1] !== p[1]) {
      points[drag.index] = p;
      changed();
    }
    return;
  }
  updateHover(event);
  askNearest(...localPosition(event));
  renderScene();
});

canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  updateHover(event);
  const [sx, sy] = localPosition(event);
  if (state.mode === 'add') {
    // Near an existing point, the new one takes its exact coordinates, so a curve can
    // be closed (P_n = P_0) or made to pass through the other curve's point.
    const p = hover ? [...state.curves[hover.curve].points[hover.index]] : view.snappedWorld(sx, sy);
    state.curves[state.active].points.push(p);
    hover = {curve: state.active, index: state.curves[state.active].points.length - 1};
    changed();
  } else if (state.mode === 'move' && hover) {
    drag = {...hover, pointerId: event.pointerId};
    canvas.setPointerCapture(event.pointerId);
    canvas.classList.add('dragging');
    event.preventDefault();
  } else if (state.mode === 'remove' && hover) {
    state.curves[hover.curve].points.splice(hover.index, 1);
    hover = null;
    updateHover(event);
    changed();
  }
});

function endDrag(event) {
  if (!drag || event.pointerId !== drag.pointerId) return;
  drag = null;
  canvas.classList.remove('dragging');
  updateHover(event);
  renderScene();
}
canvas.addEventListener('pointerup', endDrag);
canvas.addEventListener('pointercancel', endDrag);
canvas.addEventListener('pointerleave', () => {
  if (drag) return;
  hover = null;
  hoverMark = -1;
  $('tooltip').hidden = true;
  markListItems();
  nearest.clear();
});

// --- controls --------------------------------------------------------------------

function setMode(mode) {
  state.mode = mode;
  canvas.classList.remove('mode-add', 'mode-move', 'mode-remove');
  canvas.classList.add(`mode-${mode}`);
  for (const input of document.querySelectorAll('input[name=mode]')) input.checked = input.value === mode;
  renderScene();
}
for (const input of document.querySelectorAll('input[name=mode]')) {
  input.addEventListener('change', () => setMode(input.value));
}
document.addEventListener('keydown', (event) => {
  if (event.target instanceof HTMLInputElement || event.target instanceof HTMLSelectElement) return;
  if (event.ctrlKey || event.metaKey || event.altKey) return;
  const mode = {a: 'add', m: 'move', r: 'remove'}[event.key];
  if (mode) setMode(mode);
});

for (const input of document.querySelectorAll('input[name=active]')) {
  input.addEventListener('change', () => {
    state.active = Number(input.value);
    changed();
  });
}

/** t0 as the page uses it: a number rounded to two decimals and clamped to [0, 1]. */
export function normalizeT0(value) {
  const v = Number(value);
  if (!Number.isFinite(v)) return null;
  return Math.round(Math.min(1, Math.max(0, v)) * 100) / 100;
}

function setT0(value) {
  const t0 = normalizeT0(value);
  const number = $('t0-number');
  if (t0 === null || String(value).trim() === '') {
    number.value = state.t0.toFixed(2);
    return;
  }
  state.t0 = t0;
  number.value = t0.toFixed(2);
  $('t0-range').value = String(t0);
  changed();
}
$('t0-range').addEventListener('input', (event) => setT0(event.target.value));
$('t0-number').addEventListener('change', (event) => setT0(event.target.value));

const checks = {
  'show-polygon': 'polygon', 'show-curve': 'curve', 'show-points': 'points', 'show-labels': 'labels',
  'show-polar': 'polar', 'show-polar-points': 'polarPoints', 'show-loops': 'loops',
  'show-classify': 'classify', 'show-intersections': 'intersections', 'show-box': 'box',
  'show-frame': 'frame', 'show-nearest': 'nearest',
};
for (const [id, key] of Object.entries(checks)) {
  $(id).addEventListener('change', (event) => {
    state.show[key] = event.target.checked;
    if (!state.show.intersections) hoverMark = -1;
    renderScene();
    renderPanels();
  });
}

function setSecond(on) {
  state.second = on;
  $('show-second').checked = on;
  $('editing').hidden = !on;
  if (!on && state.active === 1) state.active = 0;
  if (on && state.curves[1].points.length === 0) state.active = 1;  // ready to add B's points
  for (const input of document.querySelectorAll('input[name=active]')) input.checked = Number(input.value) === state.active;
}
$('show-second').addEventListener('change', (event) => {
  setSecond(event.target.checked);
  changed();
});

$('clear').addEventListener('click', () => {
  state.curves[state.active].points = [];
  hover = null;
  hoverMark = -1;
  changed();
});

$('examples').addEventListener('change', (event) => {
  const example = kExamples[event.target.value];
  event.target.value = '';
  if (!example) return;
  state.curves[0].points = structuredClone(example.a);
  state.curves[1].points = structuredClone(example.b ?? []);
  setSecond(Boolean(example.b));
  state.active = 0;
  for (const input of document.querySelectorAll('input[name=active]')) input.checked = input.value === '0';
  changed();
});

$('download').addEventListener('click', () => {
  // The canvas is cleared to transparent and the grid is CSS: the PNG has no background.
  renderScene();
  canvas.toBlob((blob) => {
    if (!blob) return;
    const url = URL.createObjectURL(blob);
    const a = document.createElement('a');
    a.href = url;
    a.download = 'bezier-playground.png';
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10000);
  }, 'image/png');
});

$('token').value = apiToken();
$('token-form').addEventListener('submit', (event) => {
  event.preventDefault();
  setApiToken($('token').value.trim());
  answeredKey = null;  // ask again with the token
  schedule();
});

function resize() {
  if (view.resize($('canvas-wrap').clientWidth, window.devicePixelRatio)) renderScene();
}
new ResizeObserver(() => {
  resize();
  renderScene();
}).observe($('canvas-wrap'));

// For scripts and tests: the page's state and the service's answers it drew from.
window.playground = Object.freeze({
  get idle() { return isIdle(); },
  /** The control point under the cursor ({curve, index}) or null. */
  hover: () => (hover ? {...hover} : null),
  state: () => structuredClone(state),
  answers: () => structuredClone(answers),
  /** The last nearest-point answer drawn ({target, answer}) or null, and the requests sent. */
  nearest: () => {
    const n = currentNearest();
    return {result: n ? structuredClone({target: n.target, answer: n.answer}) : null, sent: nearest.sent,
            inFlight: nearest.inFlight};
  },
  errors: () => errors.map(({what, error}) => ({what, route: error.route, status: error.status, problem: error.problem})),
  /** Client (page) coordinates of world point p, for pointing at it. */
  clientPoint: (p) => {
    const rect = canvas.getBoundingClientRect();
    const [x, y] = view.toScreen(p);
    return [rect.left + x, rect.top + y];
  },
  /** The world point a click at client (x, y) adds. */
  worldAt: (x, y) => {
    const rect = canvas.getBoundingClientRect();
    return view.snappedWorld(x - rect.left, y - rect.top);
  },
});

setMode('add');
$('t0-number').value = state.t0.toFixed(2);
resize();
changed();
