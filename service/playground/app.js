// The playground: control points edited with the mouse, a finger, the keyboard, the
// table of coordinates or pasted text; everything else asked of the service. State
// changes schedule one round of requests at a time; when the state changed again while
// a round was out, one more round follows with the newest state, so dragging never
// floods the service and the last answer always matches what is on screen. Every edit
// goes through edit(): it is recorded for undo, written to the URL fragment (the
// permalink), and refused with a message beside the control that made it when it
// would go past the service's degree limit (learnt from the service's first refusal).
// A curve may instead be pasted SVG path data (path mode): it keeps the path, has no
// control points to edit, and is drawn and intersected segment by segment.

import {ApiError, apiToken, setApiToken} from './api.js';
import {drawBernstein, renderBernsteinLegend} from './bernstein.js';
import {drawCanonicalMap} from './canonical.js';
import {computeRound, usedCurves} from './compute.js';
import {LabelLayout} from './labels.js';
import {LatestRequest} from './latest.js';
import {computeOutline, defaultOutline, defaultStroke, drawOutline, kOutlineExamples, outlineSummary,
        toleranceAt} from './outline.js';
import {computeRegions, defaultRegions, drawRegions, kRegionExamples, regionsSummary, usesB, windingRequest,
        windingText} from './regions.js';
import {drawScene, kColors, kPointNames, formatNumber} from './draw.js';
import {kExamples} from './examples.js';
import {download, kExportScale, renderPng, renderSvg} from './export.js';
import {EditHistory} from './history.js';
import {markAt, pointAt} from './hit.js';
import {legendEntries, renderLegend} from './legend.js';
import {NearestTracker} from './nearest.js';
import {renderErrors, renderIntersections, renderLoops, renderTypes, renderValues, segmentsText} from './panels.js';
import {decodeFragment, encodeFragment, kLayers} from './permalink.js';
import {renderPointTable} from './pointtable.js';
import {InputError, isPathData, parsePointList, pathInDrawing, pathProblemText} from './svgpath.js';
import {View, kWorld} from './view.js';

const $ = (id) => document.getElementById(id);
const kOpeningExample = 'crossing';  // what the page shows when the link holds no drawing

const state = {
  curves: [{name: 'A', points: [], path: null}, {name: 'B', points: [], path: null}],  // path: SVG path data as pasted
  second: false,
  active: 0,
  t0: 0.5,
  mode: 'add',
  selected: null,  // {curve, index}: the point the arrow keys move
  show: {
    polygon: true, curve: true, points: true, labels: true, polar: true, polarPoints: true,
    loops: true, classify: true, intersections: true, box: true, frame: true, nearest: true,
    casteljau: true,
  },
  view: 'curves',  // or 'regions', 'outline'
  regions: defaultRegions(),  // {a, b (SVG path data), op, fillA, fillB}
  outline: defaultOutline(),  // {path (SVG path data), tolerance, distance}
};

let answers = null;  // the last round's answers (for `answered` below)
/** The last answers when they are the curves view's (each view's answers have their own shape), else null. */
const curveAnswers = () => (answers?.view === 'curves' ? answers : null);
let errors = [];
let answeredKey = null;  // request key of the state those answers are for
let inFlight = false;
let hover = null;  // {curve, index} of the control point under the cursor
let hoverMark = -1;  // index of the intersection under the cursor
let drag = null;  // {curve, index, pointerId, before}
let degreeLimit = null;  // the service's highest degree, once it has refused one
let acceptedPoints = 0;  // the most control points of a curve the service has drawn
let labels = null;  // the last drawing's label layout
let animation = null;  // {timer, direction, last} while t0 is animated

const canvas = $('scene');
const view = new View(canvas);
const history = new EditHistory();
const nearest = new NearestTracker(() => {
  renderScene();
  renderValues($('values'), state, curveAnswers(), currentNearest());
});

/** The nearest-point answer for the edited curve as it is now, or null. */
function currentNearest() {
  return state.show.nearest ? nearest.current(nearestInput()) : null;
}

/** What /nearest is asked about: the edited curve's control points, or its path as the service read it. */
function nearestInput() {
  const curve = state.curves[state.active];
  if (curve.path) {
    const path = curveAnswers()?.curves[state.active]?.path;
    return path && answeredKey === requestKey() ? {path: path.data} : null;
  }
  return curve.points.length >= 2 ? {points: curve.points} : null;
}

/** Asks for the edited curve's point nearest to canvas position (sx, sy). */
function askNearest(sx, sy) {
  const input = nearestInput();
  if (!state.show.nearest || !input) return;
  nearest.request(input, view.toWorld(sx, sy));
}

/** What the requests depend on: nothing else triggers a round. */
function requestKey() {
  if (state.view === 'regions') return JSON.stringify(['regions', state.regions]);
  if (state.view === 'outline') return JSON.stringify(['outline', state.outline]);
  return JSON.stringify([state.curves.map((c) => [c.points, c.path]), state.second, state.active, state.t0, state.show.casteljau]);
}

// The point under the pointer in the regions view, and where it winds (/contains in a /batch).
let regionPointer = null;
const winding = new LatestRequest('/batch', () => {
  renderScene();
  renderWinding();
});

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
  $('undo').disabled = !history.canUndo;
  $('redo').disabled = !history.canRedo;
}

// --- messages beside the controls ----------------------------------------------------

const kMessagePlaces = {canvas: 'canvas-message', keyboard: 'canvas-message', example: 'canvas-message',
                        link: 'canvas-message', undo: 'canvas-message', table: 'points-message',
                        paste: 'paste-message', share: 'share-message'};

function showMessage(source, text, kind = 'error') {
  const box = $(kMessagePlaces[source] ?? 'canvas-message');
  box.textContent = text;
  box.dataset.kind = kind;
  box.hidden = false;
}

function clearMessages() {
  for (const id of new Set(Object.values(kMessagePlaces))) $(id).hidden = true;
}

const limitText = (limit) => `The service draws curves of degree at most ${limit} (${limit + 1} control points)`;

/** The degree limit named by a refusal of /points in `roundErrors`, or null. */
function degreeLimitIn(roundErrors) {
  for (const {error} of roundErrors) {
    for (const e of error.problem?.errors ?? []) {
      const match = /^\/(curves\/\d+\/)?points$/.test(e.pointer ?? '') && /above the limit of (\d+)/.exec(e.message ?? '');
      if (match) return Number(match[1]);
    }
  }
  return null;
}

/** The first curve `snapshot` shows with more points than the limit allows, or null. */
function tooLong(snapshot) {
  if (degreeLimit === null) return null;
  const used = snapshot.second ? [0, 1] : [0];
  const i = used.find((k) => snapshot.points[k].length - 1 > degreeLimit);
  return i === undefined ? null : i;
}

// --- edits, undo, permalink -----------------------------------------------------------

function snapshot() {
  return structuredClone({points: state.curves.map((c) => c.points), paths: state.curves.map((c) => c.path),
                          second: state.second, active: state.active});
}

function applySnapshot(s) {
  s.points.forEach((points, i) => { state.curves[i].points = structuredClone(points); });
  s.paths.forEach((path, i) => { state.curves[i].path = path; });
  setSecond(s.second);
  setActive(s.active);
  if (state.selected && !(state.selected.index < state.curves[state.selected.curve].points.length &&
                          (state.selected.curve === 0 || state.second))) {
    state.selected = null;
  }
}

/**
 * Applies `mutate` to a copy of the edited state; when it changes something and stays
 * within the degree limit, records the old state for undo and shows the new one.
 * Returns whether the edit was made.
 */
function edit(source, mutate, merge = null) {
  const before = snapshot();
  const next = structuredClone(before);
  mutate(next);
  if (JSON.stringify(next) === JSON.stringify(before)) return false;
  const onPath = next.paths.findIndex((path, i) => path && next.points[i].length > 0);
  if (onPath >= 0) {
    showMessage(source, `Curve ${state.curves[onPath].name} is an SVG path: control-point editing is off in path mode ` +
                        '("Points mode" beside the control points turns it back on).');
    return false;
  }
  const over = tooLong(next);
  if (over !== null) {
    showMessage(source, `${limitText(degreeLimit)}: curve ${state.curves[over].name} would have ` +
                        `${next.points[over].length}, so this was not done.`);
    return false;
  }
  clearMessages();
  history.record(before, source, merge);
  applySnapshot(next);
  changed();
  return true;
}

function undo() {
  const s = history.undo(snapshot());
  if (!s) return;
  clearMessages();
  applySnapshot(s);
  changed();
}

function redo() {
  const s = history.redo(snapshot());
  if (!s) return;
  clearMessages();
  applySnapshot(s);
  changed();
}

// The fragment is rewritten at most every kFragmentInterval ms (the last state is
// always written): browsers refuse bursts of history.replaceState, and a drag or the
// t0 animation changes the state many times a second.
const kFragmentInterval = 250;
let fragmentWritten = 0;
let fragmentTimer = null;
function writeFragment() {
  const wait = fragmentWritten + kFragmentInterval - performance.now();
  if (wait > 0) {
    fragmentTimer ??= setTimeout(() => {
      fragmentTimer = null;
      writeFragment();
    }, wait);
    return;
  }
  fragmentWritten = performance.now();
  const fragment = `#${encodeFragment(state)}`;
  if (location.hash !== fragment) window.history.replaceState(null, '', fragment);
}

function readFragment(source, opening = false) {
  let decoded;
  try {
    decoded = decodeFragment(location.hash);
  } catch (e) {
    showMessage(source, `This link's drawing could not be read: ${e.message}`);
    return;
  }
  if (!decoded) return false;
  for (const layer of kLayers) setLayer(layer, !decoded.hidden.includes(layer));
  state.view = decoded.view;
  if (decoded.regions) state.regions = decoded.regions;
  if (decoded.outline) state.outline = decoded.outline;
  fillViewControls();
  const next = {points: decoded.curves, paths: decoded.paths, second: decoded.second, active: decoded.active};
  if (opening) applySnapshot(next);  // the page opens on the link's drawing: nothing to undo yet
  else edit(source, (s) => Object.assign(s, next));
  setT0(decoded.t0);
  return true;
}

// --- the rounds of requests ---------------------------------------------------------

async function schedule() {
  if (inFlight) return;
  inFlight = true;
  updateStatus();
  while (answeredKey !== requestKey()) {
    const key = requestKey();
    const snap = structuredClone({curves: state.curves, second: state.second, active: state.active, t0: state.t0,
                                  show: state.show, degreeLimit, acceptedPoints});
    let round;
    try {
      if (state.view === 'regions') round = await computeRegions(structuredClone(state.regions));
      else if (state.view === 'outline') round = await computeOutline(structuredClone(state.outline));
      else round = await computeRound(snap);
    } catch (e) {
      // An answer of an unexpected shape: say so instead of stalling.
      round = {answers: null, errors: [{what: 'drawing the answers', error: new ApiError('(page)', 0, {title: 'Page error', detail: String(e)})}]};
    }
    const limit = state.view === 'curves' ? degreeLimitIn(round.errors) : null;
    if (limit !== null && key === requestKey()) {
      // Past the degree limit: take the edit back (the drawing stays as it was) and say why.
      degreeLimit = limit;
      let refused = null;
      while (tooLong(snapshot()) !== null) {
        const entry = history.drop();
        if (!entry) break;
        applySnapshot(entry.snapshot);
        refused = entry.source;
      }
      if (refused !== null) {
        showMessage(refused, `${limitText(limit)}: that edit was not made.`);
        renderAll();
        continue;
      }
    }
    const over = state.view === 'curves' ? tooLong(snapshot()) : null;
    if (over !== null && key === requestKey()) {
      // A drawing opened past the limit (a link): its points are shown, the view says why no curve is.
      showMessage('canvas', `${limitText(degreeLimit)}: curve ${state.curves[over].name} has ` +
                            `${state.curves[over].points.length}, so only its control points are drawn. Remove ` +
                            `${state.curves[over].points.length - 1 - degreeLimit} to see the curve.`);
    }
    answers = round.answers;
    errors = round.errors;
    for (const [i, curve] of (answers?.view === 'curves' ? answers.curves : []).entries()) {
      if (curve.evaluate) acceptedPoints = Math.max(acceptedPoints, snap.curves[i].points.length);
    }
    answeredKey = key;
    renderPanels();
    renderScene();
  }
  inFlight = false;
  updateStatus();
}

function changed() {
  writeFragment();
  renderAll();
  schedule();
}

function renderAll() {
  renderScene();
  renderPanels();
}

function renderScene() {
  if (state.view !== 'curves') {
    $('hint').hidden = true;
    const ctx = view.context();
    const current = answers?.view === state.view ? answers : null;
    if (state.view === 'regions') drawRegions(ctx, view, state.regions, current, regionPointer);
    else drawOutline(ctx, view, state.outline, current);
    labels = new LabelLayout(view.cssWidth, view.cssHeight);
    updateStatus();
    return;
  }
  $('hint').hidden = state.curves.some((c) => c.points.length > 0 || c.path);
  labels = drawScene(view, state, curveAnswers(), hover, hoverMark, currentNearest());
  const active = state.active;
  const points = state.curves[active].points;
  const n = points.length - 1;
  $('bernstein-caption').textContent = n >= 1 ? `degree ${n}, curve ${state.curves[active].name}` : '';
  const emphasis = hover && hover.curve === active ? hover.index
                                                   : (state.selected?.curve === active ? state.selected.index : -1);
  drawBernstein($('bernstein'), n, emphasis, state.t0);
  updateStatus();
}

function renderDefinitions(container, rows) {
  container.replaceChildren(...rows.flatMap(([term, value]) => {
    const dt = document.createElement('dt');
    dt.textContent = term;
    const dd = document.createElement('dd');
    dd.textContent = value;
    dd.dataset.term = term.toLowerCase();
    return [dt, dd];
  }));
}

/** The winding readout for the point under the pointer, when its answer is for the drawing shown. */
function currentWinding() {
  if (state.view !== 'regions' || !regionPointer || !answers || answers.view !== 'regions' || !answers.a) return null;
  const result = winding.current(JSON.stringify([requestKey(), regionPointer]));
  return result && {names: windingRequest(answers, state.regions, regionPointer).names, answer: result.answer};
}

/** Asks where the world point under canvas position (sx, sy) winds. */
function askWinding(sx, sy) {
  if (!answers || answers.view !== 'regions' || !answers.a || answeredKey !== requestKey()) return;
  regionPointer = view.toWorld(sx, sy).map((v) => Math.round(v * 100) / 100);
  winding.request(JSON.stringify([requestKey(), regionPointer]), windingRequest(answers, state.regions, regionPointer).body);
  renderScene();
}

function renderWinding() {
  const current = currentWinding();
  $('winding').textContent = current ? windingText(current.names, current.answer, regionPointer)
                                     : 'Point at the drawing: the winding number of each shape and of the result there (/contains).';
}

function renderPanels() {
  document.body.dataset.view = state.view;
  for (const input of document.querySelectorAll('input[name=view]')) input.checked = input.value === state.view;
  if (state.view !== 'curves') {
    renderErrors({points: $('points-errors'), general: $('errors')}, errors);
    if (state.view === 'regions') {
      renderDefinitions($('region-values'), regionsSummary(state.regions, answers?.view === 'regions' ? answers : null));
      renderWinding();
    } else {
      renderDefinitions($('outline-values'), outlineSummary(state.outline, answers?.view === 'outline' ? answers : null));
    }
    return;
  }
  const active = state.active;
  const points = state.curves[active].points;
  renderValues($('values'), state, curveAnswers(), currentNearest());
  renderTypes($('types'), state, curveAnswers());
  renderIntersections($('intersections'), state, curveAnswers());
  renderLoops($('loops'), state, curveAnswers());
  renderErrors({points: $('points-errors'), general: $('errors')}, errors);
  renderBernsteinLegend($('bernstein-legend'), points.length - 1, state.t0, points, kPointNames[active]);
  renderLegend($('legend'), legendEntries(state, curveAnswers()));
  $('points-caption').textContent = `curve ${state.curves[active].name}`;
  renderPathNote();
  renderPointTable($('points-table').tBodies[0], active, points, state.selected, tableHandlers);
  const section = $('classify-section');
  section.hidden = !state.show.classify;
  if (state.show.classify) {
    const marks = usedCurves(state).map((i) => ({
      label: kPointNames[i], color: kColors.curves[i], point: curveAnswers()?.curves[i]?.classify?.canonical_point ?? null,
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
  const hit = curveAnswers().intersections.intersections[hoverMark];
  tooltip.textContent = `${hit.kind} intersection\n${segmentsText(state, hit)}t = ${formatNumber(hit.t)}, s = ${formatNumber(hit.s)}\n` +
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
  hoverMark = hover ? -1 : markAt(state, view, curveAnswers(), sx, sy, hitRadius(event));
  canvas.classList.toggle('over-point', hover !== null && state.mode !== 'add');
  showTooltip(sx, sy);
}

canvas.addEventListener('pointermove', (event) => {
  if (state.view === 'regions') {
    askWinding(...localPosition(event));
    return;
  }
  if (state.view !== 'curves') return;
  if (drag && event.pointerId === drag.pointerId) {
    const p = view.snappedWorld(...localPosition(event));
    const points = state.curves[drag.curve].points;
    const old = points[drag.index];
    if (old[0] !== p[0] || old[1] !== p[1]) {
      points[drag.index] = p;
      writeFragment();
      renderAll();
      schedule();
    }
    return;
  }
  updateHover(event);
  askNearest(...localPosition(event));
  renderScene();
});

canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0 || state.view !== 'curves') return;
  canvas.focus({preventScroll: true});  // for the keys, also when the default action is prevented below
  updateHover(event);
  const [sx, sy] = localPosition(event);
  if (state.mode === 'add') {
    // Near an existing point, the new one takes its exact coordinates, so a curve can
    // be closed (P_n = P_0) or made to pass through the other curve's point.
    const p = hover ? [...state.curves[hover.curve].points[hover.index]] : view.snappedWorld(sx, sy);
    if (edit('canvas', (s) => s.points[s.active].push(p))) {
      hover = {curve: state.active, index: state.curves[state.active].points.length - 1};
      state.selected = {...hover};
      renderAll();
    }
  } else if (state.mode === 'move' && hover) {
    // The drag edits the state directly; its start is recorded for undo when it ends.
    drag = {...hover, pointerId: event.pointerId, before: snapshot()};
    state.selected = {curve: hover.curve, index: hover.index};
    canvas.setPointerCapture(event.pointerId);
    canvas.classList.add('dragging');
    event.preventDefault();
    renderAll();
  } else if (state.mode === 'remove' && hover) {
    const {curve, index} = hover;
    if (edit('canvas', (s) => s.points[curve].splice(index, 1))) {
      hover = null;
      updateHover(event);
      renderScene();
    }
  }
});

function endDrag(event) {
  if (!drag || event.pointerId !== drag.pointerId) return;
  const {before} = drag;
  drag = null;
  if (JSON.stringify(before) !== JSON.stringify(snapshot())) {
    clearMessages();
    history.record(before, 'canvas');
  }
  canvas.classList.remove('dragging');
  updateHover(event);
  renderScene();
}
canvas.addEventListener('pointerup', endDrag);
canvas.addEventListener('pointercancel', endDrag);
canvas.addEventListener('pointerleave', () => {
  if (drag) return;
  if (regionPointer) {
    regionPointer = null;
    winding.clear();
  }
  hover = null;
  hoverMark = -1;
  $('tooltip').hidden = true;
  markListItems();
  nearest.clear();
});

// --- keyboard on the canvas -------------------------------------------------------------

function select(curve, index) {
  state.selected = index >= 0 && index < state.curves[curve].points.length ? {curve, index} : null;
  const p = state.selected && state.curves[curve].points[index];
  $('canvas-status').textContent = p ? `Selected ${kPointNames[curve]}${index} at (${p[0]}, ${p[1]})` : 'No point selected';
  renderAll();
}

canvas.addEventListener('keydown', (event) => {
  if (event.ctrlKey || event.metaKey || event.altKey || state.view !== 'curves') return;
  const active = state.active;
  const points = state.curves[active].points;
  const selected = state.selected && state.selected.curve === active ? state.selected.index : -1;
  const steps = {ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1]};
  if (event.key in steps) {
    if (selected < 0) return;
    event.preventDefault();
    const [dx, dy] = steps[event.key].map((v) => v * (event.shiftKey ? 10 : 1));
    edit('keyboard', (s) => {
      const p = s.points[active][selected];
      s.points[active][selected] = [p[0] + dx, p[1] + dy];
    }, `move ${active} ${selected}`);
    select(active, selected);
  } else if (event.key === ']' || event.key === '[') {
    event.preventDefault();
    if (points.length === 0) return;
    const next = selected < 0 ? (event.key === ']' ? 0 : points.length - 1)
                              : (selected + (event.key === ']' ? 1 : points.length - 1)) % points.length;
    select(active, next);
  } else if (event.key === 'Insert' || event.key === '+' || event.key === 'n') {
    event.preventDefault();
    // After the selected point (or the last): halfway to the next one, or 40 units on.
    const at = selected >= 0 ? selected : points.length - 1;
    let p;
    if (at < 0) p = [kWorld.width / 2, kWorld.height / 2];
    else if (at + 1 < points.length) p = points[at].map((v, k) => Math.round((v + points[at + 1][k]) / 2));
    else p = [Math.min(kWorld.width, points[at][0] + 40), points[at][1]];
    if (edit('keyboard', (s) => s.points[active].splice(at + 1, 0, p))) select(active, at + 1);
  } else if (event.key === 'Delete' || event.key === 'Backspace') {
    if (selected < 0) return;
    event.preventDefault();
    if (edit('keyboard', (s) => s.points[active].splice(selected, 1))) {
      select(active, Math.min(selected, state.curves[active].points.length - 1));
    }
  } else if (event.key === 'Escape') {
    select(active, -1);
  }
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
const typing = (target) => target instanceof HTMLInputElement || target instanceof HTMLSelectElement ||
                           target instanceof HTMLTextAreaElement;
document.addEventListener('keydown', (event) => {
  if (typing(event.target)) return;
  if ((event.ctrlKey || event.metaKey) && !event.altKey) {
    const key = event.key.toLowerCase();
    if (key === 'z' && !event.shiftKey) undo();
    else if ((key === 'z' && event.shiftKey) || key === 'y') redo();
    else return;
    event.preventDefault();
    return;
  }
  if (event.ctrlKey || event.metaKey || event.altKey) return;
  const mode = {a: 'add', m: 'move', r: 'remove'}[event.key];
  if (mode) setMode(mode);
});
$('undo').addEventListener('click', undo);
$('redo').addEventListener('click', redo);

function setActive(index) {
  state.active = index;
  for (const input of document.querySelectorAll('input[name=active]')) input.checked = Number(input.value) === index;
}
for (const input of document.querySelectorAll('input[name=active]')) {
  input.addEventListener('change', () => edit('canvas', (s) => { s.active = Number(input.value); }));
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
$('t0-range').addEventListener('input', (event) => {
  stopAnimation();
  setT0(event.target.value);
});
$('t0-number').addEventListener('change', (event) => {
  stopAnimation();
  setT0(event.target.value);
});

// Animation of t0: one step of 0.01 at a time, back and forth, each step once the
// previous one's answers are drawn (or after half a second), so every frame is whole.
function stopAnimation() {
  if (!animation) return;
  clearInterval(animation.timer);
  animation = null;
  $('animate').textContent = '▶ Animate t0';
  $('animate').setAttribute('aria-pressed', 'false');
}
$('animate').addEventListener('click', () => {
  if (animation) {
    stopAnimation();
    return;
  }
  animation = {direction: state.t0 >= 1 ? -1 : 1, last: 0};
  animation.timer = setInterval(() => {
    const now = performance.now();
    if (!isIdle() && now - animation.last < 500) return;
    if (now - animation.last < 40) return;
    animation.last = now;
    let next = Math.round((state.t0 + 0.01 * animation.direction) * 100) / 100;
    if (next > 1 || next < 0) {
      animation.direction = -animation.direction;
      next = Math.round((state.t0 + 0.01 * animation.direction) * 100) / 100;
    }
    setT0(next);
  }, 20);
  $('animate').textContent = '■ Stop';
  $('animate').setAttribute('aria-pressed', 'true');
});

const checks = {
  'show-polygon': 'polygon', 'show-curve': 'curve', 'show-points': 'points', 'show-labels': 'labels',
  'show-polar': 'polar', 'show-polar-points': 'polarPoints', 'show-loops': 'loops',
  'show-classify': 'classify', 'show-intersections': 'intersections', 'show-box': 'box',
  'show-frame': 'frame', 'show-nearest': 'nearest', 'show-casteljau': 'casteljau',
};
for (const [id, key] of Object.entries(checks)) {
  $(id).addEventListener('change', (event) => {
    state.show[key] = event.target.checked;
    if (!state.show.intersections) hoverMark = -1;
    writeFragment();  // the link keeps the layers shown
    renderAll();
    schedule();
  });
}

/** Shows or hides a layer (a name of state.show), its check box following. */
function setLayer(key, on) {
  state.show[key] = on;
  const id = Object.keys(checks).find((k) => checks[k] === key);
  if (id) $(id).checked = on;
}

function setSecond(on) {
  state.second = on;
  $('show-second').checked = on;
  $('editing').hidden = !on;
  if (!on && state.active === 1) setActive(0);
}
$('show-second').addEventListener('change', (event) => {
  const on = event.target.checked;
  event.target.checked = state.second;  // edit() sets it
  edit('canvas', (s) => {
    s.second = on;
    if (on && s.points[1].length === 0) s.active = 1;  // ready to add B's points
    if (!on) s.active = 0;
  });
});

$('clear').addEventListener('click', () => {
  hover = null;
  hoverMark = -1;
  edit('canvas', (s) => {
    s.points[s.active] = [];
    s.paths[s.active] = null;
  });
});

$('examples').addEventListener('change', (event) => {
  const example = kExamples[event.target.value];
  event.target.value = '';
  if (!example) return;
  edit('example', (s) => {
    s.points = [structuredClone(example.a), structuredClone(example.b ?? [])];
    s.paths = [null, null];
    s.second = Boolean(example.b);
    s.active = 0;
  });
});

// --- the table of control points, and pasted text ----------------------------------------

const tableHandlers = {
  onEdit: (k, axis, value) => edit('table', (s) => { s.points[s.active][k][axis] = value; }),
  onInvalid: (k, axis, text) => showMessage('table', `${kPointNames[state.active]}${k} ${axis ? 'y' : 'x'}: "${text}" is not a finite number`),
  onRemove: (k) => edit('table', (s) => { s.points[s.active].splice(k, 1); }),
  onSelect: (k) => {
    state.selected = {curve: state.active, index: k};
    renderScene();
  },
};
$('add-point').addEventListener('click', () => {
  const points = state.curves[state.active].points;
  const last = points[points.length - 1];
  const p = last ? [Math.min(kWorld.width, last[0] + 40), last[1]] : [kWorld.width / 2, kWorld.height / 2];
  edit('table', (s) => s.points[s.active].push(p));
});

/** After a paste that changed nothing and was not refused with a message: say so. */
function unchanged() {
  if ($('paste-message').hidden) showMessage('paste', 'That is the drawing already: nothing changed.', 'info');
}

$('paste-form').addEventListener('submit', async (event) => {
  event.preventDefault();
  $('paste-message').hidden = true;  // the answer's message replaces it
  const text = $('paste-text').value.trim();
  if (!isPathData(text)) {
    let points;
    try {
      points = parsePointList(text);
    } catch (e) {
      if (!(e instanceof InputError)) throw e;
      showMessage('paste', e.message);
      return;
    }
    if (edit('paste', (s) => {
      s.points[s.active] = points;
      s.paths[s.active] = null;
    })) {
      showMessage('paste', `Read ${points.length} control points from the point list.`, 'info');
    }
    unchanged();
    return;
  }
  // SVG path data: the service reads it (/segments).
  let path;
  try {
    path = await pathInDrawing(text);
  } catch (error) {
    showMessage('paste', pathProblemText(error));
    return;
  }
  const curves = path.segments;
  const n = curves.length;
  const as = $('paste-as').value;
  if (as === 'path' || (as === 'auto' && (n > 1 || path.subpaths.some((sp) => sp.closed)))) {
    const name = state.curves[state.active].name;
    if (edit('paste', (s) => {
      s.points[s.active] = [];
      s.paths[s.active] = text;
    })) {
      showMessage('paste', `Curve ${name} is SVG path data of ${n} segment${n > 1 ? 's' : ''} (read by /segments, ` +
                           'y flipped): drawn, measured and intersected as a path; its control points are not ' +
                           'editable in path mode.', 'info');
    }
    unchanged();
    return;
  }
  if (n > 2) {
    showMessage('paste', `The path has ${n} segments: as points the playground takes one (the curve being edited) or two (A and B).`);
    return;
  }
  const made = edit('paste', (s) => {
    if (n === 2) {
      s.points = curves;
      s.paths = [null, null];
      s.second = true;
      s.active = 0;
    } else {
      s.points[s.active] = curves[0];
      s.paths[s.active] = null;
    }
  });
  if (made) {
    showMessage('paste', `Read ${curves.map((c) => c.length).join(' + ')} control points from SVG path data ` +
                         `(${n} segment${n > 1 ? 's' : ''}, read by /segments, y flipped).`, 'info');
  }
  unchanged();
});

// Path mode: the note saying what is off, and the way back to control points (the
// path's first segment becomes the curve).
function renderPathNote() {
  const curve = state.curves[state.active];
  $('path-note').hidden = !curve.path;
  $('points-table').hidden = Boolean(curve.path);
  $('add-point').hidden = Boolean(curve.path);
  if (!curve.path) return;
  const path = curveAnswers()?.curves[state.active]?.path;
  const n = path ? path.segments.length : null;
  $('path-note-text').textContent =
      `Curve ${curve.name} is an SVG path${n ? ` of ${n} segment${n > 1 ? 's' : ''}` : ''} (path mode): drawn, ` +
      'measured (length, box, nearest point), searched for loops and self-intersections and intersected as a ' +
      'path. Its control points cannot be edited, and the panels that need one curve\'s control points (polar, ' +
      'de Casteljau, Bernstein basis, frame, type) are off for it.';
}
$('points-mode').addEventListener('click', async () => {
  const {path} = state.curves[state.active];
  if (!path) return;
  let first;
  try {
    first = (await pathInDrawing(path)).segments[0];
  } catch (error) {
    showMessage('paste', pathProblemText(error));
    return;
  }
  edit('canvas', (s) => {
    s.paths[s.active] = null;
    s.points[s.active] = first;
  });
});

// --- the regions and outline views ---------------------------------------------------

function setView(name) {
  if (state.view === name) return;
  state.view = name;
  regionPointer = null;
  winding.clear();
  nearest.clear();
  clearMessages();
  fillViewControls();
  changed();
}
for (const input of document.querySelectorAll('input[name=view]')) {
  input.addEventListener('change', () => setView(input.value));
}

/** The regions and outline controls from the state (after a link or an example). */
function fillViewControls() {
  const r = state.regions;
  $('region-a').value = r.a;
  $('region-b').value = r.b;
  $('region-op').value = r.op;
  $('fill-a').value = r.fillA;
  $('fill-b').value = r.fillB;
  $('region-b').disabled = !usesB(r);
  $('fill-b').disabled = !usesB(r);
  const o = state.outline;
  $('outline-path').value = o.path;
  $('tolerance').value = String(Math.log10(o.tolerance));
  $('tolerance-value').textContent = String(o.tolerance);
  $('distance').value = String(o.distance);
  $('distance-value').textContent = String(o.distance);
  const stroke = o.stroke ?? defaultStroke();
  $('stroke-on').checked = Boolean(o.stroke);
  $('stroke-width').value = String(stroke.width);
  $('stroke-width-value').textContent = String(stroke.width);
  $('stroke-join').value = stroke.join;
  $('stroke-cap').value = stroke.cap;
  for (const id of ['stroke-width', 'stroke-join', 'stroke-cap']) $(id).disabled = !o.stroke;
}

function fillExamples(select, examples) {
  for (const [key, example] of Object.entries(examples)) {
    const option = document.createElement('option');
    option.value = key;
    option.textContent = example.label;
    select.append(option);
  }
}
fillExamples($('region-examples'), kRegionExamples);
fillExamples($('outline-examples'), kOutlineExamples);

function setRegions(next) {
  state.regions = {...state.regions, ...next};
  regionPointer = null;
  winding.clear();
  fillViewControls();
  changed();
}
$('region-examples').addEventListener('change', (event) => {
  const example = kRegionExamples[event.target.value];
  event.target.value = '';
  if (!example) return;
  const {a, b, op, fillA, fillB} = example;
  $('region-message').hidden = true;
  setRegions({a, b: b || state.regions.b, op, fillA, fillB});
});
$('region-op').addEventListener('change', (event) => setRegions({op: event.target.value}));
$('fill-a').addEventListener('change', (event) => setRegions({fillA: event.target.value}));
$('fill-b').addEventListener('change', (event) => setRegions({fillB: event.target.value}));
$('region-form').addEventListener('submit', (event) => {
  event.preventDefault();
  const a = $('region-a').value.trim();
  const b = $('region-b').value.trim();
  const message = $('region-message');
  if (!a || (usesB(state.regions) && !b)) {
    message.textContent = usesB(state.regions) ? 'Both shapes need path data.' : 'Shape A needs path data.';
    message.dataset.kind = 'error';
    message.hidden = false;
    return;
  }
  message.hidden = true;
  setRegions({a, b});
});

function setOutline(next) {
  state.outline = {...state.outline, ...next};
  fillViewControls();
  changed();
}
$('outline-examples').addEventListener('change', (event) => {
  const example = kOutlineExamples[event.target.value];
  event.target.value = '';
  if (example) setOutline({path: example.path});
});
$('outline-form').addEventListener('submit', (event) => {
  event.preventDefault();
  const path = $('outline-path').value.trim();
  if (!path) {
    $('outline-message').textContent = 'The outline needs path data.';
    $('outline-message').dataset.kind = 'error';
    $('outline-message').hidden = false;
    return;
  }
  $('outline-message').hidden = true;
  setOutline({path});
});
$('tolerance').addEventListener('input', (event) => setOutline({tolerance: toleranceAt(Number(event.target.value))}));
$('distance').addEventListener('input', (event) => setOutline({distance: Number(event.target.value)}));
$('stroke-on').addEventListener('change', (event) => setOutline({stroke: event.target.checked ? defaultStroke() : null}));
const setStroke = (change) => setOutline({stroke: {...(state.outline.stroke ?? defaultStroke()), ...change}});
$('stroke-width').addEventListener('input', (event) => setStroke({width: Number(event.target.value)}));
$('stroke-join').addEventListener('change', (event) => setStroke({join: event.target.value}));
$('stroke-cap').addEventListener('change', (event) => setStroke({cap: event.target.value}));

// --- sharing and pictures ------------------------------------------------------------

$('copy-link').addEventListener('click', async () => {
  writeFragment();
  try {
    await navigator.clipboard.writeText(location.href);
    showMessage('share', 'Link copied: it opens this drawing.', 'info');
  } catch {
    showMessage('share', `Copy this link: ${location.href}`, 'info');
  }
});

$('download').addEventListener('click', () => {
  const png = renderPng(state, curveAnswers(), view.cssWidth, legendEntries(state, curveAnswers()));
  png.toBlob((blob) => { if (blob) download(blob, 'bezier-playground.png'); }, 'image/png');
});
$('download-svg').addEventListener('click', () => {
  download(new Blob([renderSvg(state, curveAnswers())], {type: 'image/svg+xml'}), 'bezier-playground.svg');
});

$('token').value = apiToken();
$('token-form').addEventListener('submit', (event) => {
  event.preventDefault();
  setApiToken($('token').value.trim());
  answeredKey = null;  // ask again with the token
  schedule();
});

// The canvas keeps the drawing's aspect ratio and is as large as the column allows,
// but no taller than what leaves the t0 row in the window, so the main controls fit
// a laptop screen without scrolling.
const kBelowCanvas = 56;  // CSS pixels for the t0 row under the canvas
function resize() {
  const wrap = $('canvas-wrap');
  const available = $('stage').clientWidth - 2;
  const top = wrap.getBoundingClientRect().top + window.scrollY;
  const tallest = Math.max(240, window.innerHeight - top - kBelowCanvas - 2);
  const width = Math.min(available, Math.floor(tallest * kWorld.width / kWorld.height));
  wrap.style.width = `${width + 2}px`;
  if (view.resize(width, window.devicePixelRatio)) renderScene();
}
new ResizeObserver(() => {
  resize();
  renderScene();
}).observe($('stage'));
window.addEventListener('resize', resize);
window.addEventListener('hashchange', () => {
  if (location.hash !== `#${encodeFragment(state)}`) readFragment('link');
});

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
  /** The canvas labels as placed ({text, x, y, w, h} in CSS pixels), those left out, and the
   *  marks' discs (as boxes) and rings they keep clear of. */
  labels: () => ({placed: labels.boxes(), dropped: [...labels.dropped], ...labels.obstacles()}),
  /** Undo and redo depths, and the degree limit once the service has named it. */
  history: () => ({undo: history.past.length, redo: history.future.length}),
  degreeLimit: () => degreeLimit,
  exportScale: kExportScale,
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
fillViewControls();
resize();
if (!location.hash || !readFragment('link', true)) {
  // No drawing in the link: open on an example rather than an empty grid.
  const example = kExamples[kOpeningExample];
  applySnapshot({points: [structuredClone(example.a), structuredClone(example.b ?? [])], paths: [null, null],
                 second: Boolean(example.b), active: 0});
}
changed();
