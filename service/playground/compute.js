// One round of requests for a snapshot of the page's state. Everything the page draws
// comes from these answers: the sampled curves (/evaluate), the first polar (/polar),
// the loops and their areas (/loop-area), the intersections and overlaps
// (/intersections), the cubic's type and canonical point (/classify), the edited
// curve's frame at t0 (/evaluate with frame), tight box (/bounds) and lengths (/length
// of the curve and of [0, t0]), de Casteljau's construction at t0 (/polar with t0
// repeated r times: the r-th polar's control points are the construction's level r),
// and the points on loops, overlaps, inflections, cusps and the box's extremes
// (/evaluate at the parameters those answers gave). A curve in path mode is its pasted
// path data read by the service (/segments): its segments are drawn from the control
// points that answer gives, and the path routes answer for the whole path: its loops and
// enclosed area (/loop-area), its self-intersections (/intersections of the path alone),
// its length (/length) and box (/bounds). Each request fails on its own: its problem is
// collected and the rest is drawn.

import {post} from './api.js';
import {pathInDrawing} from './svgpath.js';

export const kCurveSamples = 257;  // uniform samples of a curve (0 and 1 included)
export const kPolarSamples = 129;
const kPieceSamples = 97;  // samples of a loop or an overlapping piece

/** The curves a round works on: A always, B when the second curve is on. */
export function usedCurves(state) {
  return state.second ? [0, 1] : [0];
}

function piece(interval) {
  const [a, b] = interval;
  const ts = [];
  for (let i = 0; i < kPieceSamples; ++i) ts.push(a + (b - a) * i / (kPieceSamples - 1));
  ts[kPieceSamples - 1] = b;
  return ts;
}

/** How a curve is sent: its path (drawing units, from `resolved`) in path mode, else its control points. */
function curveInput(curve, resolved) {
  return curve.path ? {path: resolved.data} : {points: curve.points};
}

/**
 * Sends the requests for `state` and resolves to {answers, errors}; never rejects.
 * answers.curves[i]: {evaluate, loopArea, classify, loopPaths, overlapPaths, features,
 * path (in path mode: the path /segments made of the pasted data, see svgpath.js),
 * selfIntersections (in path mode: /intersections of the path alone), tooLong (the
 * curve is past the degree limit: state.degreeLimit, or the refusal of its first request
 * when it has more control points than state.acceptedPoints, the most the service has
 * taken so far; nothing else was asked about it)}
 * answers.polar: the /polar answer for the active curve (with .curve = its index);
 * answers.measure: for the active curve, {curve, frame (the /evaluate result at t0 with
 * frame), bounds (the /bounds answer), extremes ([{axis, t, point}] at its critical
 * parameters), length, lengthToT0 (the /length answers on [0, 1] and [0, t0])};
 * answers.casteljau: with state.show.casteljau, {curve, t0, levels} where levels[r] is
 * the list b_0^r .. b_{n-r}^r (levels[0] the control points, levels[n] [B(t0)]);
 * answers.intersections: the /intersections answer for A and B (a curve in path mode
 * sent as {path}, so each answer names its `segments`).
 * answers.measure for a path: {curve, path: true, length, bounds} (no frame or t0).
 * errors: [{what, error}] with error an ApiError.
 */
export async function computeRound(state) {
  const errors = [];
  const attempt = async (what, route, body) => {
    try {
      return await post(route, body);
    } catch (error) {
      errors.push({what, error});
      return null;
    }
  };
  const used = usedCurves(state);
  const curves = state.curves.map(() => ({
    evaluate: null, loopArea: null, classify: null, loopPaths: [], overlapPaths: [], features: [], path: null,
    selfIntersections: null, tooLong: false,
  }));
  const answers = {view: 'curves', curves, polar: null, measure: null, casteljau: null, intersections: null};
  // Paths first: every other request about a path sends what /segments made of it.
  await Promise.all(used.filter((i) => state.curves[i].path).map(async (i) => {
    try {
      curves[i].path = await pathInDrawing(state.curves[i].path);
    } catch (error) {
      errors.push({what: `path data of ${state.curves[i].name}`, error});
    }
  }));
  const ready = (i) => (state.curves[i].path ? curves[i].path !== null : state.curves[i].points.length >= 2);
  // A curve of more control points than the service has taken so far, while its limit is not
  // known, is sampled alone first: when that is refused for its degree, every other request
  // about it would be refused alike, so none is sent.
  const probed = new Set();
  await Promise.all(used.map(async (i) => {
    const {name, points, path} = state.curves[i];
    if (path || points.length < 2 || state.degreeLimit !== null || points.length <= (state.acceptedPoints ?? 0)) return;
    probed.add(i);
    const before = errors.length;
    curves[i].evaluate = await attempt(`curve ${name}`, '/evaluate', {points, samples: kCurveSamples});
    if (errors.slice(before).some(({error}) => isDegreeRefusal(error))) curves[i].tooLong = true;
  }));
  const jobs = [];
  for (const i of used) {
    const {name, points, path} = state.curves[i];
    if (!path && state.degreeLimit !== null && points.length - 1 > state.degreeLimit) {
      curves[i].tooLong = true;  // refused already: its requests would all fail alike
    }
    if (curves[i].tooLong) continue;
    if (path) {
      if (!ready(i)) continue;
      const data = curves[i].path.data;
      jobs.push(attempt(`loops of ${name}`, '/loop-area', {path: data}).then((a) => { curves[i].loopArea = a; }));
      jobs.push(attempt(`self-intersections of ${name}`, '/intersections', {curves: [{path: data}]})
          .then((a) => { curves[i].selfIntersections = a; }));
      continue;
    }
    if (points.length < 2) continue;
    if (!probed.has(i)) {
      jobs.push(attempt(`curve ${name}`, '/evaluate', {points, samples: kCurveSamples})
          .then((a) => { curves[i].evaluate = a; }));
    }
    if (points.length >= 3) {
      jobs.push(attempt(`loops of ${name}`, '/loop-area', {points})
          .then((a) => { curves[i].loopArea = a; }));
    }
    if (points.length === 4) {
      jobs.push(attempt(`type of ${name}`, '/classify', {points})
          .then((a) => { curves[i].classify = a; }));
    }
  }
  const active = used.includes(state.active) ? state.active : 0;
  const activeCurve = state.curves[active];
  if (activeCurve.path && ready(active)) {
    jobs.push(measurePath(state, active, answers, attempt));
  } else if (!activeCurve.path && activeCurve.points.length >= 2 && !curves[active].tooLong) {
    const activePoints = activeCurve.points;
    const polar = attempt(`polar of ${activeCurve.name}`, '/polar',
                          {points: activePoints, t0: state.t0, samples: kPolarSamples})
        .then((a) => { if (a) answers.polar = {...a, curve: active}; });
    jobs.push(polar);
    if (state.show.casteljau) jobs.push(construction(state, active, answers, attempt, polar));
    jobs.push(measure(state, active, answers, attempt));
  }
  if (state.second && ready(0) && ready(1) && !curves[0].tooLong && !curves[1].tooLong) {
    jobs.push(attempt('intersections of A and B', '/intersections',
                      {curves: [curveInput(state.curves[0], curves[0].path), curveInput(state.curves[1], curves[1].path)]})
        .then((a) => { answers.intersections = a; }));
  }
  await Promise.all(jobs);
  await Promise.all(used.map((i) => (state.curves[i].path ? pointsOnPath(state, answers, i, attempt)
                                                          : pointsOnCurve(state, answers, i, attempt))));
  return {answers, errors};
}

/** Whether the service refused a curve for its degree (a 422 pointing at the control points). */
export function isDegreeRefusal(error) {
  return (error.problem?.errors ?? []).some((e) => /^\/(curves\/\d+\/)?points$/.test(e.pointer ?? '') &&
                                                   /above the limit of \d+/.test(e.message ?? ''));
}

/** The measuring answers for a path: its length and box (no t0: a path has no single parameter). */
async function measurePath(state, active, answers, attempt) {
  const {name} = state.curves[active];
  const data = answers.curves[active].path.data;
  const m = {curve: active, frame: null, bounds: null, extremes: [], length: null, lengthToT0: null, path: true};
  answers.measure = m;
  await Promise.all([
    attempt(`length of ${name}`, '/length', {path: data}).then((a) => { m.length = a; }),
    attempt(`box of ${name}`, '/bounds', {path: data}).then((a) => { m.bounds = a; }),
  ]);
}

/** The points of a path's loops: each loop's piece, segment by segment, from /evaluate. */
async function pointsOnPath(state, answers, i, attempt) {
  const curve = answers.curves[i];
  const loops = curve.loopArea?.loops ?? [];
  const segments = curve.path?.segments;
  if (!segments || loops.length === 0) return;
  await Promise.all(loops.map(async (loop) => {
    const [first, last] = loop.segments;
    const pieces = [];
    for (let k = first; k <= last; ++k) {
      const from = k === first ? loop.t[0] : 0;
      const to = k === last ? loop.t[1] : 1;
      pieces.push(attempt(`loop of ${state.curves[i].name}`, '/evaluate', {points: segments[k], t: piece([from, to])}));
    }
    const answered = await Promise.all(pieces);
    if (answered.some((a) => !a)) return;
    curve.loopPaths.push({loop, points: answered.flatMap((a) => a.results.map((r) => r.point))});
  }));
}

/** De Casteljau's levels at t0: level r from the r-th polar b(t0, ..., t0, t, ..., t). */
async function construction(state, active, answers, attempt, polarDone) {
  const {name, points} = state.curves[active];
  const n = points.length - 1;
  const levels = Array(n + 1).fill(null);
  levels[0] = points;
  const jobs = [];
  for (let r = 2; r < n; ++r) {
    jobs.push(attempt(`de Casteljau level ${r} of ${name}`, '/polar', {points, t0: Array(r).fill(state.t0)})
        .then((a) => { levels[r] = a?.control_points ?? null; }));
  }
  await Promise.all([polarDone, ...jobs]);
  const polar = answers.polar;
  if (!polar) return;
  levels[1] = polar.control_points;
  levels[n] = [polar.curve_point];
  if (levels.every((level) => level !== null)) answers.casteljau = {curve: active, t0: state.t0, levels};
}

/** The measuring answers for the active curve: frame at t0, box, lengths. */
async function measure(state, active, answers, attempt) {
  const {name, points} = state.curves[active];
  const m = {curve: active, frame: null, bounds: null, extremes: [], length: null, lengthToT0: null};
  answers.measure = m;
  await Promise.all([
    attempt(`frame of ${name} at t0`, '/evaluate', {points, t: state.t0, frame: true})
        .then((a) => { m.frame = a?.results[0] ?? null; }),
    attempt(`length of ${name}`, '/length', {points})
        .then((a) => { m.length = a; }),
    attempt(`length of ${name} on [0, t0]`, '/length', {points, interval: [0, state.t0]})
        .then((a) => { m.lengthToT0 = a; }),
    attempt(`box of ${name}`, '/bounds', {points}).then(async (a) => {
      m.bounds = a;
      const wanted = (a?.critical ?? []).flatMap((ts, axis) => ts.map((t) => ({axis, t})));
      if (wanted.length === 0) return;
      const at = await attempt(`extremes of ${name}`, '/evaluate', {points, t: wanted.map((w) => w.t)});
      if (at) m.extremes = wanted.map((w, k) => ({...w, point: at.results[k].point}));
    }),
  ]);
}

/** Second stage: the points of curve i at the parameters the first answers named. */
async function pointsOnCurve(state, answers, i, attempt) {
  const curve = answers.curves[i];
  const wanted = [];  // {kind, ts, ...}
  for (const loop of curve.loopArea?.loops ?? []) {
    wanted.push({kind: 'loop', ts: piece(loop.t), loop});
  }
  // A path's overlaps are listed by segment, not drawn along the path.
  const overlaps = state.curves[i].path ? [] : answers.intersections?.overlaps ?? [];
  for (const overlap of overlaps) {
    const interval = i === 0 ? overlap.t_interval : overlap.s_interval;
    if (Array.isArray(interval)) wanted.push({kind: 'overlap', ts: piece(interval)});
  }
  // A curve that retraces itself (collinear control points) overlaps itself: both pieces.
  for (const overlap of curve.loopArea?.overlaps ?? []) {
    for (const interval of [overlap.t_interval, overlap.s_interval]) {
      if (Array.isArray(interval)) wanted.push({kind: 'overlap', ts: piece(interval)});
    }
  }
  const c = curve.classify;
  if (c) {
    for (const t of c.inflections ?? []) wanted.push({kind: 'inflection', ts: [t], t});
    if (typeof c.cusp === 'number') wanted.push({kind: 'cusp', ts: [c.cusp], t: c.cusp});
  }
  if (wanted.length === 0) return;
  const ts = wanted.flatMap((w) => w.ts);
  const answer = await attempt(`points on ${state.curves[i].name}`, '/evaluate',
                               {points: state.curves[i].points, t: ts});
  if (!answer) return;
  let k = 0;
  for (const w of wanted) {
    const points = answer.results.slice(k, k + w.ts.length).map((r) => r.point);
    k += w.ts.length;
    if (w.kind === 'loop') curve.loopPaths.push({loop: w.loop, points});
    else if (w.kind === 'overlap') curve.overlapPaths.push(points);
    else curve.features.push({kind: w.kind, t: w.t, point: points[0]});
  }
}
