// Curves typed or pasted as text: a list of points ("100,120 240,480 …", or JSON
// [[100, 120], …]) in the drawing's units (y up), or SVG path data made of M, L, Q and C
// commands, absolute or relative (m, l, q, c), in SVG's y-down units of the same
// 800 x 600 drawing (so a path drawn in an 800 x 600 SVG lands where it was drawn).
// Every L, Q or C is one Bézier segment (degree 1, 2 or 3). Other commands (H, V, S,
// T, A, Z) have no single Bézier curve to give and are refused with a message.
// Also the way back: the path data of a curve of degree 1 to 3.

import {kWorld} from './view.js';

export class InputError extends Error {}

const kNumber = /[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?/y;
const kCommand = /[A-Za-z]/y;
const kSeparator = /[\s,]*/y;

/** SVG path data to tokens: {command} or {number}; throws InputError on other text. */
function tokens(text) {
  const out = [];
  let at = 0;
  const skip = () => {
    kSeparator.lastIndex = at;
    kSeparator.exec(text);
    at = kSeparator.lastIndex;
  };
  skip();
  while (at < text.length) {
    kCommand.lastIndex = at;
    kNumber.lastIndex = at;
    let m;
    if ((m = kCommand.exec(text))) {
      out.push({command: m[0]});
      at = kCommand.lastIndex;
    } else if ((m = kNumber.exec(text))) {
      out.push({number: Number(m[0])});
      at = kNumber.lastIndex;
    } else {
      throw new InputError(`unexpected "${text.slice(at, at + 8)}" at character ${at + 1} of the path data`);
    }
    skip();
  }
  return out;
}

const kPointsPerSegment = {L: 1, Q: 2, C: 3};

/** The Bézier segments of SVG path data, each as control points in SVG units (y down). */
export function parsePathData(text) {
  const list = tokens(text);
  const segments = [];
  let current = null;
  let k = 0;
  if (!list.length || !list[0].command || list[0].command.toUpperCase() !== 'M') {
    throw new InputError('path data starts with M (or m)');
  }
  while (k < list.length) {
    const letter = list[k].command;
    if (!letter) throw new InputError(`number ${list[k].number} without a command`);
    const upper = letter.toUpperCase();
    if (!'MLQC'.includes(upper)) {
      throw new InputError(`the ${letter} command is not supported: only M, L, Q and C (and m, l, q, c) give Bézier curves`);
    }
    const relative = letter !== upper && current !== null;
    ++k;
    const numbers = [];
    while (k < list.length && list[k].number !== undefined) numbers.push(list[k++].number);
    if (numbers.length === 0 || numbers.length % 2) throw new InputError(`${letter} needs pairs of numbers`);
    const pairs = [];
    for (let j = 0; j < numbers.length; j += 2) pairs.push([numbers[j], numbers[j + 1]]);
    let segmentType = upper;
    if (upper === 'M') {
      const [first, ...rest] = pairs;
      current = relative ? [current[0] + first[0], current[1] + first[1]] : first;
      if (!rest.length) continue;
      pairs.splice(0, pairs.length, ...rest);  // further pairs are an implicit L (or l)
      segmentType = 'L';
    }
    const per = kPointsPerSegment[segmentType];
    if (pairs.length % per) throw new InputError(`${letter} needs ${per * 2} numbers per segment`);
    if (current === null) throw new InputError('path data starts with M (or m)');
    for (let j = 0; j < pairs.length; j += per) {
      const origin = current;
      const points = pairs.slice(j, j + per).map((p) => (relative ? [origin[0] + p[0], origin[1] + p[1]] : p));
      segments.push([origin, ...points]);
      current = points[points.length - 1];
    }
  }
  if (!segments.length) throw new InputError('the path draws nothing: add an L, Q or C after M');
  return segments;
}

/** SVG units (y down) and the drawing's (y up). */
export const fromSvg = ([x, y]) => [x, kWorld.height - y];
export const toSvg = ([x, y]) => [x, kWorld.height - y];

/**
 * Text to curves (drawing units): {curves: [points, ...], source: 'path' | 'list'}.
 * Throws InputError with a message for the user.
 */
export function parseCurveText(text) {
  const trimmed = text.trim();
  if (!trimmed) throw new InputError('nothing to read: paste points or SVG path data');
  if (/^[A-Za-z]/.test(trimmed)) {
    return {curves: parsePathData(trimmed).map((segment) => segment.map(fromSvg)), source: 'path'};
  }
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
  return {curves: [points], source: 'list'};
}

/** SVG path data for a curve of degree 1, 2 or 3 (drawing units in, SVG units out); else null. */
export function pathData(points) {
  const command = {2: 'L', 3: 'Q', 4: 'C'}[points.length];
  if (!command) return null;
  const [first, ...rest] = points.map(toSvg);
  return `M ${first.join(' ')} ${command} ${rest.map((p) => p.join(' ')).join(' ')}`;
}

const kSegmentCommand = {2: 'L', 3: 'Q', 4: 'C'};

/**
 * Pasted SVG path data (SVG units, y down) as a path of the drawing: {segments (control
 * points in drawing units, y up, numbered as the service numbers them), data (the same
 * path as SVG path data in drawing units, for the service)}. Throws InputError.
 */
export function pathInDrawing(text) {
  const segments = parsePathData(text.trim()).map((segment) => segment.map(fromSvg));
  const parts = [];
  let end = null;
  for (const [first, ...rest] of segments) {
    if (!end || end[0] !== first[0] || end[1] !== first[1]) parts.push(`M ${first.join(' ')}`);
    parts.push(`${kSegmentCommand[rest.length + 1]} ${rest.map((p) => p.join(' ')).join(' ')}`);
    end = rest[rest.length - 1];
  }
  return {segments, data: parts.join(' ')};
}
