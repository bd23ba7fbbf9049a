// Text typed or pasted as curves. SVG path data is read by the service (POST /segments:
// one grammar, the service's, with every command SVG has, arcs as cubics): its segments
// come back in SVG's y-down units of the 800 x 600 drawing, are turned into the drawing's
// y-up units here, and are written back as path data of degree-1 to 3 commands (Z where
// a subpath is closed), which every path route then reads the same way. A point list
// ("100,120 240,480 …", or JSON [[100, 120], …]) is in the drawing's units and needs no
// grammar. Also the way back: the path data of a curve of degree 1 to 3 (SVG export).

import {ApiError, post} from './api.js';
import {kWorld} from './view.js';

export class InputError extends Error {}

/** SVG units (y down) and the drawing's (y up). */
export const fromSvg = ([x, y]) => [x, kWorld.height - y];
export const toSvg = ([x, y]) => [x, kWorld.height - y];

/** Whether pasted text is SVG path data (it starts with a command letter) rather than a point list. */
export const isPathData = (text) => /^\s*[A-Za-z]/.test(text);

/** A point list as the control points of one curve (drawing units); throws InputError. */
export function parsePointList(text) {
  const trimmed = text.trim();
  if (!trimmed) throw new InputError('nothing to read: paste points or SVG path data');
  let numbers;
  if (trimmed.startsWith('[')) {
    let parsed;
    try {
      parsed = JSON.parse(trimmed);
    } catch (e) {
      throw new InputError(`not a JSON list of points: ${e.message}`);
    }
    if (!Array.isArray(parsed) || !parsed.every((p) => Array.isArray(p) && p.length === 2)) {
      throw new InputError('a JSON list of points is [[x, y], [x, y], …]');
    }
    numbers = parsed.flat();
  } else {
    const words = trimmed.split(/[\s,;()]+/).filter(Boolean);
    numbers = words.map(Number);
    const bad = words.findIndex((w, k) => Number.isNaN(numbers[k]));
    if (bad >= 0) throw new InputError(`"${words[bad]}" is not a number`);
    if (numbers.length % 2) throw new InputError(`${numbers.length} numbers: points need an x and a y each`);
  }
  if (!numbers.every((v) => typeof v === 'number' && Number.isFinite(v))) {
    throw new InputError('every coordinate must be a finite number');
  }
  const points = [];
  for (let k = 0; k < numbers.length; k += 2) points.push([numbers[k], numbers[k + 1]]);
  if (points.length < 2) throw new InputError('a curve needs at least two points');
  return points;
}

const kSegmentCommand = {2: 'L', 3: 'Q', 4: 'C'};
const commandFor = (points) => `${kSegmentCommand[points.length]} ${points.slice(1).map((p) => p.join(' ')).join(' ')}`;

/** SVG path data for a curve of degree 1, 2 or 3 (drawing units in, SVG units out); else null. */
export function pathData(points) {
  if (!kSegmentCommand[points.length]) return null;
  const svg = points.map(toSvg);
  return `M ${svg[0].join(' ')} ${commandFor(svg)}`;
}

/**
 * The /segments answer for SVG path data (SVG units) as a path of the drawing:
 * {segments (control points, drawing units, numbered as the service numbers them),
 * closing (per segment: the closing line of a Z), subpaths (the answer's), data (path
 * data in drawing units for the path routes: the same segments, Z for a closed subpath),
 * arcTolerance (the answer's arc_tolerance or null)}.
 */
export function pathFromSegments(answer) {
  const segments = answer.segments.map((s) => s.points.map(fromSvg));
  const parts = [];
  for (const subpath of answer.subpaths) {
    const first = subpath.first_segment;
    parts.push(`M ${segments[first][0].join(' ')}`);
    for (let k = first; k < first + subpath.segment_count; ++k) {
      if (answer.segments[k].closing) continue;  // Z draws it
      parts.push(commandFor(segments[k]));
    }
    if (subpath.closed) parts.push('Z');
  }
  return {segments, closing: answer.segments.map((s) => s.closing), subpaths: answer.subpaths, data: parts.join(' '),
          arcTolerance: answer.arc_tolerance ?? null};
}

const cache = new Map();  // pasted text -> Promise of pathFromSegments(...), oldest first
const kCacheSize = 64;  // texts kept: the paths of a session's drawings, links and examples

/**
 * Pasted SVG path data (SVG units) as a path of the drawing (see pathFromSegments),
 * from the service's /segments; answers are kept per text. Rejects with the ApiError
 * the service sent (its message names the offset in the text).
 */
export function pathInDrawing(text) {
  const key = text.trim();
  if (!cache.has(key)) {
    const promise = post('/segments', {path: key}).then(pathFromSegments);
    promise.catch(() => cache.delete(key));  // a refusal is asked again, e.g. after a token is entered
    cache.set(key, promise);
    if (cache.size > kCacheSize) cache.delete(cache.keys().next().value);
  }
  return cache.get(key);
}

/** The message of a /segments refusal for the user: the service's own, field by field. */
export function pathProblemText(error) {
  if (!(error instanceof ApiError)) return String(error?.message ?? error);
  const fields = error.problem?.errors ?? [];
  if (fields.length) return `the service could not read the path data: ${fields.map((e) => e.message).join('; ')}`;
  return `${error.status || 'no answer'} ${error.problem?.title ?? ''}: ${error.problem?.detail ?? ''}`.trim();
}
