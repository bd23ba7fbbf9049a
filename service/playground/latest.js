// A request that follows the pointer: at most one is out at a time; a newer one that
// arrives meanwhile waits (replacing any older waiting one) and is sent when the answer
// comes, so moving the pointer never floods the service and the last position is
// always answered. An answer counts only while what it was asked about is unchanged.

import {post} from './api.js';

export class LatestRequest {
  /** route: where to POST; onChange(): called whenever the answer or the request state changes. */
  constructor(route, onChange) {
    this.route = route;
    this.onChange = onChange;
    this.inFlight = false;
    this.waiting = null;  // {key, body} to send when the current request returns
    this.result = null;  // {key, body, answer} of the last answer, or null
    this.error = null;  // the ApiError of the last request, or null
    this.sent = 0;
    this.generation = 0;  // bumped by clear(), so an answer already on its way is dropped
  }

  /** Sends `body`; `key` names what it is about (see current). */
  request(key, body) {
    this.waiting = {key, body: structuredClone(body)};
    if (!this.inFlight) this.#sendWaiting();
  }

  clear() {
    this.waiting = null;
    this.result = null;
    ++this.generation;
    this.onChange();
  }

  /** The last answer if it was asked about `key`, else null. */
  current(key) {
    return this.result && this.result.key === key ? this.result : null;
  }

  async #sendWaiting() {
    while (this.waiting) {
      const {key, body} = this.waiting;
      this.waiting = null;
      this.inFlight = true;
      ++this.sent;
      const generation = this.generation;
      try {
        const answer = await post(this.route, body);
        if (generation === this.generation) this.result = {key, body, answer};
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
