// The nearest point of the edited curve (its control points, or a path's data) to the
// pointer (/nearest). The pointer moves far more often than the service can answer, so
// the requests follow it one at a time (LatestRequest: a position that arrives meanwhile
// waits, replacing any older waiting one), and an answer counts only while the curve it
// was asked about is still the one on screen.

import {LatestRequest} from './latest.js';

export class NearestTracker {
  /** onChange() is called whenever the answer or the request state changes. */
  constructor(onChange) {
    this.latest = new LatestRequest('/nearest', onChange);
  }

  /** Asks for the point of `input` ({points} or {path}) nearest to `target` (world units). */
  request(input, target) {
    this.latest.request(JSON.stringify(input), {...input, targets: [[...target]]});
  }

  /** Forgets the answer (the pointer left, or the feature was turned off). */
  clear() {
    this.latest.clear();
  }

  /** The last answer ({input, target, answer}) if it is for `input`, else null. */
  current(input) {
    const result = input ? this.latest.current(JSON.stringify(input)) : null;
    return result && {input, target: result.body.targets[0], answer: result.answer.results[0]};
  }

  /** Requests sent, for tests and diagnostics. */
  get sent() {
    return this.latest.sent;
  }

  get inFlight() {
    return this.latest.inFlight;
  }
}
