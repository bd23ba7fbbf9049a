// Pictures to download: a PNG of the drawing at twice the screen's resolution on white
// with the legend under it, and an SVG of the curves, control polygons and points
// (curves of degree 1 to 3 as exact SVG path commands, higher degrees as the service's
// samples).

import {drawScene, kColors, kPointNames, pointColor} from './draw.js';
import {drawLegend, legendHeight} from './legend.js';
import {pathData, toSvg} from './svgpath.js';
import {View, kWorld} from './view.js';

export const kExportScale = 2;

/** A canvas with the scene drawn at kExportScale, white behind it, the legend below. */
export function renderPng(state, answers, cssWidth, entries) {
  const canvas = document.createElement('canvas');
  const view = new View(canvas);
  view.resize(cssWidth, kExportScale);
  const measure = canvas.getContext('2d');
  const legend = legendHeight(measure, entries, view.cssWidth);
  const drawing = view.cssHeight;
  canvas.height = Math.round((drawing + legend) * kExportScale);
  drawScene(view, {...state, selected: null}, answers, null, -1, null);  // no hover, selection or pointer marks
  const ctx = canvas.getContext('2d');
  ctx.setTransform(kExportScale, 0, 0, kExportScale, 0, 0);
  ctx.strokeStyle = '#d5dae1';
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.moveTo(0, drawing + 0.5);
  ctx.lineTo(view.cssWidth, drawing + 0.5);
  ctx.stroke();
  drawLegend(ctx, entries, 0, drawing, view.cssWidth);
  ctx.globalCompositeOperation = 'destination-over';  // white behind everything drawn
  ctx.fillStyle = '#ffffff';
  ctx.fillRect(0, 0, view.cssWidth, drawing + legend);
  return canvas;
}

const fixed = (v) => String(Number(v.toFixed(4)));
const svgPoint = (p) => toSvg(p).map(fixed).join(' ');
const escapeXml = (text) => text.replace(/[<>&"]/g, (c) => ({'<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;'}[c]));

/** An SVG document of the curves shown, in the drawing's 800 x 600 units (y down, as SVG has it). */
export function renderSvg(state, answers) {
  const parts = [
    `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${kWorld.width} ${kWorld.height}" width="${kWorld.width}" height="${kWorld.height}">`,
    `<rect width="${kWorld.width}" height="${kWorld.height}" fill="#ffffff"/>`,
  ];
  for (const i of state.second ? [0, 1] : [0]) {
    const {name, points} = state.curves[i];
    if (points.length === 0) continue;
    const color = kColors.curves[i];
    if (points.length >= 2) {
      parts.push(`<polyline id="polygon-${name}" points="${points.map((p) => toSvg(p).map(fixed).join(',')).join(' ')}" ` +
                 'fill="none" stroke="#7b8794" stroke-dasharray="5 4"/>');
      const exact = pathData(points);
      const samples = answers?.curves[i]?.evaluate?.results.map((r) => r.point);
      const d = exact ?? (samples ? `M ${samples.map(svgPoint).join(' L ')}` : null);
      if (d) parts.push(`<path id="curve-${name}" d="${d}" fill="none" stroke="${color}" stroke-width="3"/>`);
    }
    points.forEach((p, k) => {
      const [x, y] = toSvg(p).map(fixed);
      const fill = i === state.active ? pointColor(k) : '#ffffff';
      parts.push(`<circle cx="${x}" cy="${y}" r="5" fill="${fill}" stroke="${color}" stroke-width="2"/>`);
      parts.push(`<text x="${fixed(Number(x) + 8)}" y="${fixed(Number(y) - 8)}" font-family="sans-serif" font-size="13" ` +
                 `fill="${color}">${escapeXml(`${kPointNames[i]}${k}`)}</text>`);
    });
  }
  parts.push('</svg>');
  return `${parts.join('\n')}\n`;
}

/** Offers `blob` as a download named `name`. */
export function download(blob, name) {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}
