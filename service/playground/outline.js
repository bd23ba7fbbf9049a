// The outline view: one path (SVG path data, pasted or from the examples, in SVG's
// y-down units of the 800 x 600 drawing) read by the service (/segments), flattened
// within a tolerance (/flatten: polylines whose vertices lie on the path) and offset at
// a signed distance within the same tolerance (/offset: cubics of the parallel curve,
// positive to the left of the direction of travel, y up). The tolerance slider is
// logarithmic, so each step scales it alike; the drawing follows it and the distance.
// On request the path is also stroked (/stroke: width, join, cap, within the same
// tolerance); the outline it answers, SVG path data in the drawing's units, is read back
// by /segments and filled under the nonzero rule. A service without /stroke answers
// 404, which is shown like any refusal: the rest of the view does not depend on it.

import {post} from './api.js';
import {formatNumber, tracePath} from './draw.js';
import {pathInDrawing} from './svgpath.js';

export const kOutlineColors = Object.freeze({path: '#7b8794', polyline: '#8a3fd1', vertex: '#8a3fd1', offset: '#d81b60'});

// Paths in SVG units (y down).
export const kOutlineExamples = Object.freeze({
  glyph: {label: 'A glyph (a D)', path: 'M 230 520 L 230 80 C 480 80 600 190 600 300 C 600 410 480 520 230 520 Z'},
  wave: {label: 'An S-curve with tight turns', path: 'M 90 330 C 200 20 360 40 400 300 C 440 560 600 580 710 270'},
  arc: {label: 'A half circle (arc) and a line', path: 'M 160 400 A 240 240 0 0 1 640 400 L 160 400'},
});

/** Tolerance: the slider holds log10 of it. */
export const kToleranceRange = Object.freeze({min: -2, max: 1.5, step: 0.05});
export const kDistanceRange = Object.freeze({min: -120, max: 120, step: 1});

/** stroke: null (not stroked) or {width, join, cap}. */
export const defaultOutline = () => ({path: kOutlineExamples.glyph.path, tolerance: 0.5, distance: -30, stroke: null});
export const defaultStroke = () => ({width: 40, join: 'round', cap: 'round'});

/** The tolerance a slider position stands for, rounded to 3 significant digits. */
export const toleranceAt = (exponent) => Number((10 ** exponent).toPrecision(3));

/**
 * The answers for `outline`: {view: 'outline', path (as the service read it), flatten,
 * offset (the /flatten and /offset answers)}, and the failed requests. Never rejects.
 */
export async function computeOutline(outline) {
  const errors = [];
  const answers = {view: 'outline', path: null, flatten: null, offset: null, stroke: null};
  try {
    answers.path = await pathInDrawing(outline.path);
  } catch (error) {
    errors.push({what: 'path data of the outline', error});
    return {answers, errors};
  }
  const data = answers.path.data;
  const ask = async (key, route, body) => {
    try {
      answers[key] = await post(route, body);
    } catch (error) {
      errors.push({what: `${route.slice(1)} of the path`, error});
    }
  };
  await Promise.all([
    ask('flatten', '/flatten', {path: data, tolerance: outline.tolerance}),
    outline.distance !== 0 ? ask('offset', '/offset', {path: data, distance: outline.distance, tolerance: outline.tolerance})
                           : null,
    outline.stroke ? stroke(outline, data, answers, errors) : null,
  ]);
  return {answers, errors};
}

/** The stroked outline: /stroke's path, read back by /segments (drawing units, no flip). */
async function stroke(outline, data, answers, errors) {
  const {width, join, cap} = outline.stroke;
  let outlinePath;
  try {
    outlinePath = (await post('/stroke', {path: data, width, join, cap, tolerance: outline.tolerance})).path;
  } catch (error) {
    errors.push({what: 'stroke of the path', error});
    return;
  }
  if (!outlinePath) {
    answers.stroke = {segments: [], subpaths: []};
    return;
  }
  try {
    const read = await post('/segments', {path: outlinePath});
    answers.stroke = {segments: read.segments.map((s) => s.points), subpaths: read.subpaths};
  } catch (error) {
    errors.push({what: 'segments of the stroke', error});
  }
}

/** Draws the path, the flattened polylines with their vertices, and the offset cubics. */
export function drawOutline(ctx, view, outline, answers) {
  if (!answers || answers.view !== 'outline' || !answers.path) return;
  if (answers.stroke) {
    ctx.save();
    tracePath(ctx, view, answers.stroke);
    ctx.fillStyle = 'rgba(31, 111, 209, 0.18)';
    ctx.fill('nonzero');
    ctx.strokeStyle = '#1f6fd1';
    ctx.lineWidth = 1.25;
    ctx.stroke();
    ctx.restore();
  }
  ctx.save();
  tracePath(ctx, view, answers.path);
  ctx.strokeStyle = kOutlineColors.path;
  ctx.lineWidth = 5;
  ctx.globalAlpha = 0.35;
  ctx.stroke();
  ctx.restore();
  if (answers.offset) {
    ctx.save();
    ctx.strokeStyle = kOutlineColors.offset;
    ctx.lineWidth = 2.5;
    let end = null;
    ctx.beginPath();
    for (const {points} of answers.offset.segments) {
      const start = view.toScreen(points[0]);
      if (!end || end[0] !== points[0][0] || end[1] !== points[0][1]) ctx.moveTo(...start);
      ctx.bezierCurveTo(...points.slice(1).flatMap((p) => view.toScreen(p)));
      end = points[3];
    }
    ctx.stroke();
    ctx.fillStyle = kOutlineColors.offset;
    for (const {points} of answers.offset.segments) {
      const [x, y] = view.toScreen(points[0]);
      ctx.fillRect(x - 2.5, y - 2.5, 5, 5);
    }
    ctx.restore();
  }
  if (answers.flatten) {
    ctx.save();
    ctx.strokeStyle = kOutlineColors.polyline;
    ctx.lineWidth = 1.25;
    for (const polyline of answers.flatten.polylines) {
      ctx.beginPath();
      polyline.forEach((p, k) => (k ? ctx.lineTo(...view.toScreen(p)) : ctx.moveTo(...view.toScreen(p))));
      ctx.stroke();
    }
    for (const polyline of answers.flatten.polylines) {
      for (const p of polyline) {
        const [x, y] = view.toScreen(p);
        ctx.beginPath();
        ctx.arc(x, y, 3, 0, 2 * Math.PI);
        ctx.fillStyle = kOutlineColors.vertex;
        ctx.fill();
      }
    }
    ctx.restore();
  }
}

/** The values shown beside the drawing. */
export function outlineSummary(outline, answers) {
  const a = answers?.view === 'outline' ? answers : null;
  return [
    ['Segments', a?.path ? String(a.path.segments.length) : '—'],
    ['Tolerance', formatNumber(outline.tolerance)],
    ['Vertices', a?.flatten ? `${a.flatten.count} in ${a.flatten.polylines.length} polyline${a.flatten.polylines.length === 1 ? '' : 's'}` : '—'],
    ['Offset', outline.distance === 0 ? 'distance 0: none' :
               (a?.offset ? `${a.offset.segments.length} cubics at d = ${formatNumber(outline.distance)}, ` +
                            `certified within ${formatNumber(a.offset.error_bound)}` : '—')],
    ['Stroke', !outline.stroke ? 'off' :
               (a?.stroke ? `width ${formatNumber(outline.stroke.width)}, ${outline.stroke.join} joins, ${outline.stroke.cap} caps: ` +
                            `${a.stroke.segments.length} segments in ${a.stroke.subpaths.length} contour${a.stroke.subpaths.length === 1 ? '' : 's'}`
                          : '—')],
  ];
}
