// The legend: one entry per kind of mark the canvas shows at the moment, each with a
// small drawing of the mark and a line saying what it is. The same entries are drawn
// into the side panel (a small canvas each) and under the drawing in the PNG export.

import {drawFeatureMark, drawKindMarker, kColors, levelColor, pointColor} from './draw.js';

const line = (color, width, dash = []) => (ctx, w, h) => {
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.setLineDash(dash);
  ctx.beginPath();
  ctx.moveTo(2, h / 2);
  ctx.lineTo(w - 2, h / 2);
  ctx.stroke();
  ctx.setLineDash([]);
};

const disc = (fill, stroke, radius) => (ctx, w, h) => {
  ctx.beginPath();
  ctx.arc(w / 2, h / 2, radius, 0, 2 * Math.PI);
  ctx.fillStyle = fill;
  ctx.fill();
  ctx.lineWidth = 2;
  ctx.strokeStyle = stroke;
  ctx.stroke();
};

const cross = (rotated) => (ctx, w, h) => drawFeatureMark(ctx, w / 2, h / 2, rotated);

/** The entries for what `state` shows, given the last `answers` (may be null). */
export function legendEntries(state, answers) {
  const show = state.show;
  const entries = [];
  const add = (id, text, swatch) => entries.push({id, text, swatch});
  const n = state.curves[state.active].points.length - 1;
  if (show.points) {
    add('points', 'Control points Pᵢ (= bᵢ⁰); on the curve being edited each has the colour of its Bernstein weight',
        (ctx, w, h) => {
          for (let i = 0; i < 3; ++i) disc(pointColor(i), kColors.curves[state.active], 4)(ctx, w / 3 + i * 9 - w / 6, h);
        });
  }
  if (show.polygon) add('polygon', 'Control polygon', line('#7b8794', 1, [5, 4]));
  if (show.curve) {
    add('curve-a', 'Curve A, B(t) for t in [0, 1] (/evaluate)', line(kColors.curves[0], 3));
    if (state.second) add('curve-b', 'Curve B', line(kColors.curves[1], 2.25));
  }
  if (show.polar) add('polar', 'First polar at t₀: the curve b(t₀, t, …, t) of degree n − 1, tangent to B at B(t₀) (/polar)', line(kColors.polar, 2));
  if (show.polarPoints || show.casteljau) {
    add('polar-points', 'bᵢ¹: the first polar\'s control points, which are level 1 of de Casteljau\'s construction', (ctx, w, h) => {
      ctx.fillStyle = kColors.polar;
      ctx.fillRect(w / 2 - 4, h / 2 - 4, 8, 8);
    });
  }
  if (show.casteljau && n >= 3) {
    add('levels', 'bᵢʳ: level r of de Casteljau\'s construction at t₀, bᵢʳ = (1 − t₀) bᵢʳ⁻¹ + t₀ bᵢ₊₁ʳ⁻¹ (/polar with t₀ repeated r times)', (ctx, w, h) => {
      for (let r = 2; r <= Math.min(n - 1, 4); ++r) {
        ctx.beginPath();
        ctx.arc(6 + (r - 2) * 9, h / 2, 3.5, 0, 2 * Math.PI);
        ctx.fillStyle = levelColor(r);
        ctx.fill();
      }
    });
  }
  if (show.polar || show.casteljau) add('curve-point', 'B(t₀): the last level of the construction, the point of the curve', disc('#ffffff', kColors.polar, 4.5));
  if (show.frame) {
    add('tangent', 'Unit tangent and normal at t₀ (/evaluate with frame)', (ctx, w, h) => {
      line(kColors.tangent, 2)(ctx, w * 0.6, h);
      ctx.strokeStyle = kColors.normal;
      ctx.beginPath();
      ctx.moveTo(w * 0.75, h - 2);
      ctx.lineTo(w * 0.75, 2);
      ctx.stroke();
    });
    add('osculating', 'Osculating circle at t₀: radius 1/|κ|, centre B(t₀) + N/κ (κ the signed curvature)', (ctx, w, h) => {
      ctx.strokeStyle = kColors.osculating;
      ctx.lineWidth = 1.25;
      ctx.beginPath();
      ctx.arc(w / 2, h / 2, h / 2 - 2, 0, 2 * Math.PI);
      ctx.stroke();
    });
  }
  if (show.box) {
    add('box', 'Tight box of the curve and its extreme points (/bounds)', (ctx, w, h) => {
      ctx.strokeStyle = kColors.box;
      ctx.setLineDash([6, 3]);
      ctx.strokeRect(3, 3, w - 6, h - 6);
      ctx.setLineDash([]);
      ctx.fillStyle = '#ffffff';
      ctx.beginPath();
      ctx.moveTo(w / 2, 0);
      ctx.lineTo(w / 2 + 4, 4);
      ctx.lineTo(w / 2, 8);
      ctx.lineTo(w / 2 - 4, 4);
      ctx.closePath();
      ctx.fill();
      ctx.stroke();
    });
  }
  if (show.nearest) add('nearest', 'Nearest point of the curve to the pointer, and its distance d (/nearest)', line(kColors.nearest, 1.5, [4, 3]));
  if (show.loops) {
    add('loop', 'Self-intersection loop, shaded, with its area and double point (/loop-area)', (ctx, w, h) => {
      ctx.globalAlpha = 0.22;
      ctx.fillStyle = kColors.curves[0];
      ctx.fillRect(2, 2, w - 4, h - 4);
      ctx.globalAlpha = 1;
    });
  }
  if (show.intersections && state.second) {
    add('overlap', 'Overlap: the curves coincide on a piece', line(kColors.overlap, 8));
    for (const kind of ['transversal', 'tangent', 'degenerate']) {
      const what = {transversal: 'the curves cross', tangent: 'they touch (parallel tangents)',
                    degenerate: 'a derivative vanishes there'}[kind];
      add(`kind-${kind}`, `Intersection, ${kind}: ${what} (/intersections)`, (ctx, w, h) => drawKindMarker(ctx, w / 2, h / 2, kind, 6, false));
    }
  }
  if (show.classify) {
    add('inflection', 'Inflection: the curvature changes sign (/classify)', cross(false));
    add('cusp', 'Cusp: B\'(t) = 0, the curve turns back', cross(true));
  }
  return entries;
}

export const kSwatch = Object.freeze({width: 34, height: 16});

/** The entries as a list: a small canvas with the mark, then the text. */
export function renderLegend(container, entries) {
  const ratio = Math.max(1, window.devicePixelRatio || 1);
  container.replaceChildren(...entries.map((entry) => {
    const li = document.createElement('li');
    li.dataset.mark = entry.id;
    const canvas = document.createElement('canvas');
    canvas.width = kSwatch.width * ratio;
    canvas.height = kSwatch.height * ratio;
    canvas.className = 'legend-swatch';
    canvas.setAttribute('aria-hidden', 'true');
    const ctx = canvas.getContext('2d');
    ctx.scale(ratio, ratio);
    entry.swatch(ctx, kSwatch.width, kSwatch.height);
    li.append(canvas, entry.text);
    return li;
  }));
}

/** Lines the text of each entry needs at `width`, and the legend's height in CSS pixels. */
export function legendHeight(ctx, entries, width) {
  ctx.font = '12px system-ui, sans-serif';
  return 12 + entries.reduce((h, e) => h + wrap(ctx, e.text, width - kSwatch.width - 24).length * 16 + 4, 0);
}

function wrap(ctx, text, width) {
  const lines = [];
  let current = '';
  for (const word of text.split(' ')) {
    const next = current ? `${current} ${word}` : word;
    if (current && ctx.measureText(next).width > width) {
      lines.push(current);
      current = word;
    } else {
      current = next;
    }
  }
  if (current) lines.push(current);
  return lines;
}

/** Draws the legend at (x, y) across `width` CSS pixels (the PNG export's). */
export function drawLegend(ctx, entries, x, y, width) {
  ctx.save();
  ctx.font = '12px system-ui, sans-serif';
  ctx.textBaseline = 'top';
  ctx.fillStyle = '#1b1f24';
  let at = y + 8;
  for (const entry of entries) {
    ctx.save();
    ctx.translate(x + 8, at);
    entry.swatch(ctx, kSwatch.width, kSwatch.height);
    ctx.restore();
    const lines = wrap(ctx, entry.text, width - kSwatch.width - 24);
    ctx.fillStyle = '#1b1f24';
    lines.forEach((text, k) => ctx.fillText(text, x + kSwatch.width + 16, at + 1 + k * 16));
    at += lines.length * 16 + 4;
  }
  ctx.restore();
}
