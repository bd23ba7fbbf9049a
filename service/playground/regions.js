// The regions view: two shapes (SVG path data, pasted or from the examples, in SVG's
// y-down units of the 800 x 600 drawing), each with its fill rule, and an operation.
// The service reads each shape (/segments), combines them (/boolean: union,
// intersection, difference, xor, or simplify of the first alone) and says where the
// point under the pointer winds (/contains, for each shape and the result, in one
// /batch). The result is filled, its contours outlined, and every result segment drawn
// in the colour of the shape it is a piece of (the answer names each one's `source`).

import {post} from './api.js';
import {formatNumber, tracePath} from './draw.js';
import {pathInDrawing} from './svgpath.js';

export const kRegionColors = Object.freeze({a: '#1f6fd1', b: '#d35400', fill: 'rgba(39, 174, 96, 0.28)', contour: '#1e8449'});

// Shapes in SVG units (y down), so they read as they would in an 800 x 600 SVG.
export const kRegionExamples = Object.freeze({
  blobs: {label: 'Two round shapes (cubics)', op: 'union', fillA: 'nonzero', fillB: 'nonzero',
          a: 'M 150 300 C 150 80 470 80 470 300 C 470 520 150 520 150 300 Z',
          b: 'M 330 300 C 330 120 650 120 650 300 C 650 480 330 480 330 300 Z'},
  squares: {label: 'Two overlapping squares', op: 'union', fillA: 'nonzero', fillB: 'nonzero',
            a: 'M 150 150 H 450 V 450 H 150 Z', b: 'M 320 230 H 650 V 520 H 320 Z'},
  ring: {label: 'A ring (arcs, even-odd) and a bar', op: 'difference', fillA: 'evenodd', fillB: 'nonzero',
         a: 'M 180 300 A 220 220 0 0 1 620 300 A 220 220 0 0 1 180 300 Z M 280 300 A 120 120 0 0 1 520 300 A 120 120 0 0 1 280 300 Z',
         b: 'M 100 265 H 700 V 335 H 100 Z'},
  glyph: {label: 'A glyph\'s overlapping strokes (simplify)', op: 'simplify', fillA: 'nonzero', fillB: 'nonzero',
          a: 'M 200 150 H 600 V 230 H 200 Z M 360 100 H 440 V 500 H 360 Z M 250 420 Q 400 330 560 470 L 540 500 Q 400 390 270 450 Z',
          b: ''},
});

export const defaultRegions = () => {
  const {a, b, op, fillA, fillB} = kRegionExamples.blobs;
  return {a, b, op, fillA, fillB};
};

/** Whether the operation takes the second shape. */
export const usesB = (regions) => regions.op !== 'simplify';

/**
 * The answers for `regions`: {view: 'regions', a, b (the shapes as the service read them,
 * see svgpath.js, or null), boolean (the /boolean answer or null), request (what was
 * sent to /boolean)}, and the failed requests as [{what, error}]. Never rejects.
 */
export async function computeRegions(regions) {
  const errors = [];
  const answers = {view: 'regions', a: null, b: null, boolean: null, request: null};
  const read = async (key, name) => {
    if (!regions[key].trim()) return;
    try {
      answers[key] = await pathInDrawing(regions[key]);
    } catch (error) {
      errors.push({what: `path data of shape ${name}`, error});
    }
  };
  await Promise.all([read('a', 'A'), usesB(regions) ? read('b', 'B') : null]);
  if (!answers.a || (usesB(regions) && !answers.b)) return {answers, errors};
  const request = {op: regions.op, a: {path: answers.a.data, fill_rule: regions.fillA}};
  if (usesB(regions)) request.b = {path: answers.b.data, fill_rule: regions.fillB};
  answers.request = request;
  try {
    answers.boolean = await post('/boolean', request);
  } catch (error) {
    errors.push({what: `the ${regions.op} of the shapes`, error});
  }
  return {answers, errors};
}

/** The /batch body asking where `target` winds: in each shape, and in the result (nonzero). */
export function windingRequest(answers, regions, target) {
  const items = [{path: '/contains', body: {path: answers.a.data, fill_rule: regions.fillA, targets: [target]}}];
  const names = ['A'];
  if (usesB(regions) && answers.b) {
    items.push({path: '/contains', body: {path: answers.b.data, fill_rule: regions.fillB, targets: [target]}});
    names.push('B');
  }
  if (answers.boolean?.path) {
    items.push({path: '/contains', body: {path: answers.boolean.path, fill_rule: 'nonzero', targets: [target]}});
    names.push('result');
  }
  return {body: {requests: items}, names};
}

/** The readout of a winding answer: one line per region. */
export function windingText(names, batch, target) {
  const parts = names.map((name, k) => {
    const item = batch.responses[k];
    if (item.status !== 200) return `${name}: ${item.status} ${item.body.title ?? ''}`;
    const r = item.body.results[0];
    if (r.boundary) return `${name}: on the boundary`;
    return `${name}: winding ${r.winding}, ${r.inside ? 'inside' : 'outside'}`;
  });
  if (!names.includes('result')) parts.push('result: empty');
  return `At (${formatNumber(target[0])}, ${formatNumber(target[1])}): ${parts.join('; ')}`;
}

/** A Bézier segment of degree 1 to 3 as a canvas command from its start (already current). */
function curveTo(ctx, view, points) {
  const q = points.slice(1).flatMap((p) => view.toScreen(p));
  if (q.length === 2) ctx.lineTo(...q);
  else if (q.length === 4) ctx.quadraticCurveTo(...q);
  else ctx.bezierCurveTo(...q);
}

/** Draws the shapes, the result and the pointer's mark; `pointer` is a world point or null. */
export function drawRegions(ctx, view, regions, answers, pointer) {
  if (!answers || answers.view !== 'regions') return;
  const shapes = [['a', regions.fillA], ...(usesB(regions) ? [['b', regions.fillB]] : [])];
  for (const [key, rule] of shapes) {
    const path = answers[key];
    if (!path) continue;
    ctx.save();
    tracePath(ctx, view, path);
    ctx.globalAlpha = 0.08;
    ctx.fillStyle = kRegionColors[key];
    ctx.fill(rule);
    ctx.globalAlpha = 0.7;
    ctx.strokeStyle = kRegionColors[key];
    ctx.setLineDash([6, 4]);
    ctx.lineWidth = 1.25;
    ctx.stroke();
    ctx.restore();
  }
  const result = answers.boolean;
  if (result) {
    // The result's contours, filled (nonzero: outer counter-clockwise, holes clockwise).
    ctx.save();
    ctx.beginPath();
    for (const {segments: [from, to]} of result.contours) {
      if (to <= from) continue;
      ctx.moveTo(...view.toScreen(result.segments[from].points[0]));
      for (let k = from; k < to; ++k) curveTo(ctx, view, result.segments[k].points);
      ctx.closePath();
    }
    ctx.fillStyle = kRegionColors.fill;
    ctx.fill('nonzero');
    ctx.strokeStyle = kRegionColors.contour;
    ctx.lineWidth = 7;
    ctx.globalAlpha = 0.25;
    ctx.stroke();
    ctx.restore();
    // Each segment in its source's colour, its ends marked.
    ctx.save();
    ctx.lineWidth = 3;
    ctx.lineCap = 'round';
    for (const segment of result.segments) {
      ctx.strokeStyle = kRegionColors[segment.source];
      ctx.beginPath();
      ctx.moveTo(...view.toScreen(segment.points[0]));
      curveTo(ctx, view, segment.points);
      ctx.stroke();
    }
    for (const segment of result.segments) {
      const [x, y] = view.toScreen(segment.points[0]);
      ctx.beginPath();
      ctx.arc(x, y, 3, 0, 2 * Math.PI);
      ctx.fillStyle = '#ffffff';
      ctx.fill();
      ctx.strokeStyle = '#1b1f24';
      ctx.lineWidth = 1;
      ctx.stroke();
    }
    ctx.restore();
  }
  if (pointer) {
    const [x, y] = view.toScreen(pointer);
    ctx.save();
    ctx.strokeStyle = '#1b1f24';
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    ctx.moveTo(x - 7, y);
    ctx.lineTo(x + 7, y);
    ctx.moveTo(x, y - 7);
    ctx.lineTo(x, y + 7);
    ctx.stroke();
    ctx.restore();
  }
}

/** The result's summary: area, contours, segments by source. */
export function regionsSummary(regions, answers) {
  const result = answers?.view === 'regions' ? answers.boolean : null;
  if (!result) return [];
  const bySource = {a: 0, b: 0};
  for (const s of result.segments) ++bySource[s.source];
  const holes = result.contours.filter((c) => c.orientation === 'cw').length;
  return [
    ['Operation', `${regions.op}${usesB(regions) ? ` of A (${regions.fillA}) and B (${regions.fillB})` : ` of A (${regions.fillA})`}`],
    ['Area', formatNumber(result.area)],
    ['Contours', result.contours.length ? `${result.contours.length} (${holes} hole${holes === 1 ? '' : 's'}, clockwise)` : 'none: the result is empty'],
    ['Segments', `${result.segments.length}: ${bySource.a} from A, ${bySource.b} from B`],
  ];
}
