// The nearest point of the edited curve (its control points, or a path's data) to the pointer (/nearest). The pointer moves
// far more often than the service can answer, so at most one request is out at a time:
// a position that arrives meanwhile waits, replacing any older waiting one, and is
// sent when the answer comes. An answer counts only while the curve it was asked for
// is still the one on screen.

import {post} from './api.js';

export class NearestTracker {
  /** onChange() is called whenever the answer or the request state changes. */
  constructor(onChange) {
    this.onChange = onChange;
    this.inFlight = false;
    this.waiting = null;  // {input, target} to send when the current request returns
    this.result = null;  // {input, target, answer} of the last answer, or null
    this.error = null;  // the ApiError of the last request, or null
    this.sent = 0;  // requests sent, for tests and diagnostics
    this.generation = 0;  // bumped by clear(), so an answer already on its way is dropped
  }

  /** Asks for the point of `input` ({points} or {path}) nearest to `target` (world units). */
  request(input, target) {
    this.waiting = {input: structuredClone(input), target: [...target]};
    if (!this.inFlight) this.#sendWaiting();
  }

  /** Forgets the answer (the pointer left, or the feature was turned off). */
  clear() {
    this.waiting = null;
    this.result = null;
    ++this.generation;
    this.onChange();
  }

  /** The last answer if it is for `input`, else null. */
  current(input) {
    if (!this.result || !input || JSON.stringify(this.result.input) !== JSON.stringify(input)) return null;
    return this.result;
  }

  async #sendWaiting() {
    while (this.waiting) {
      const {input, target} = this.waiting;
      this.waiting = null;
      this.inFlight = true;
      ++this.sent;
      const generation = this.generation;
      try {
        const answer = await post('/nearest', {...input, targets: [target]});
        if (generation === this.generation) this.result = {input, target, answer: answer.results[0]};
        this.error = null;
      } catch (error) {
        this.result = null;
        this.error = error;
      }
      this.inFlight = false;
      this.onChange();
    }
  }
}
