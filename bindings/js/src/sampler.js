// Sampler: one pds_sampler handle in the WebAssembly module's memory.
import {
  CanceledError, DONE, ECANCELED, EINTERNAL, InternalError, MORE, StateError, errorFor,
} from './errors.js';
import { init, registerCallbacks, unregisterCallbacks } from './wasm.js';
import {
  boundingBox, fixedArrays, maskBytes, polygonArrays, radiusMapValues, toSize, toThreads,
  withRingLabel,
} from './options.js';

const UNIT_SQUARE = [0, 0, 1, 1];
const registry = typeof FinalizationRegistry !== 'undefined'
  ? new FinalizationRegistry(({ api, handle, id }) => {
    if (api.broken === null) api.exports.pds_destroy(handle);
    unregisterCallbacks(id);
  })
  : null;

function cString(api, ptr) {
  if (ptr === 0) return '';
  const bytes = new Uint8Array(api.memory.buffer, ptr);
  return new TextDecoder().decode(bytes.subarray(0, bytes.indexOf(0)));
}

function strerrorOf(api, code) { return cString(api, api.exports.pds_strerror(code)); }

// fn(...pointers) with each typed array copied into the module's memory (null
// stays a NULL pointer), freed after. The views are made once every malloc is
// done, as a malloc may grow (and so replace) the memory's buffer.
function withCopies(api, arrays, fn) {
  const ex = api.exports;
  const ptrs = [];
  try {
    for (const a of arrays) {
      const p = a === null ? 0 : ex.malloc(Math.max(a.byteLength, 8));
      if (a !== null && p === 0) throw errorFor(-2, `malloc of ${a.byteLength} bytes failed`, strerrorOf(api, -2));
      ptrs.push(p);
    }
    arrays.forEach((a, i) => {
      if (a !== null) new Uint8Array(api.memory.buffer, ptrs[i], a.byteLength).set(new Uint8Array(a.buffer, a.byteOffset, a.byteLength));
    });
    return fn(...ptrs);
  } finally {
    for (const p of ptrs) if (p !== 0) ex.free(p);
  }
}

// A random seed (Node 18 has Web Crypto only as node:crypto's webcrypto).
async function randomSeed() {
  const crypto = globalThis.crypto ?? (await import('node:crypto')).webcrypto;
  const words = crypto.getRandomValues(new Uint32Array(2));
  return (BigInt(words[0]) << 32n) | BigInt(words[1]);
}

function toSeed(seed) {
  const value = typeof seed === 'bigint' ? seed : Number.isSafeInteger(seed) ? BigInt(seed) : null;
  if (value === null || value < 0n || value >= 1n << 64n) {
    throw new TypeError(`seed must be an integer in [0, 2**64) (a number or a BigInt), got ${seed}`);
  }
  return value;
}


export class Sampler {
  #api;
  #handle = 0;
  #id = 0;
  #calls = 0;          // calls into the library now running (callbacks may read only)
  #errors = [];        // what the callbacks threw during the current call
  #progress = null;
  #radiusFn = null;
  #signal = null;
  #yieldAt = Infinity; // runAsync: the time after which the progress callback pauses the run
  #paused = false;
  seed;
  bounds;
  periodic;

  constructor(key) {
    if (key !== Sampler.#key) throw new TypeError('use `await Sampler.create(radius, options)`');
  }
  static #key = Symbol('Sampler');

  /**
   * A sampler. radius may be null with `count`, `radiusMap` or `radius`
   * (a function). See index.d.ts for the options.
   */
  static async create(radius, options = {}) {
    const api = await init();
    const s = new Sampler(Sampler.#key);
    const seed = options.seed ?? await randomSeed();
    s.#setup(api, radius, { ...options, seed });
    return s;
  }

  #setup(api, radius, options) {
    const {
      seed, bounds = UNIT_SQUARE, periodic = false, count, radiusMap,
      rmin, rmax, progress, signal, polygon, mask, fixed, threads,
    } = options;
    let { radiusFn } = options;
    if (typeof radius === 'function') {  // create((x, y) => r, { rmin, rmax })
      if (radiusFn !== undefined) throw new TypeError('give the radius function once');
      radiusFn = radius;
      radius = null;
    }
    this.#api = api;
    if (api.broken) throw this.#trapped(api.broken);
    this.seed = toSeed(seed);
    if (!Array.isArray(bounds) && !ArrayBuffer.isView(bounds) || bounds.length !== 4) {
      throw new TypeError(`bounds must be [x0, y0, x1, y1], got ${bounds}`);
    }
    this.bounds = Array.from(bounds, Number);
    if (polygon !== undefined && (mask !== undefined || options.bounds !== undefined)) {
      throw new TypeError('give polygon alone: its bounding box is the domain\'s rectangle (bounds goes with a rectangle or a mask)');
    }
    // Shapes are checked before the library sees anything; values by the library.
    const rings = polygon !== undefined ? polygonArrays(polygon) : null;
    const raster = mask !== undefined ? maskBytes(mask) : null;
    const points = fixed !== undefined ? fixedArrays(fixed) : null;
    if (threads !== undefined) toThreads(threads);
    this.periodic = Boolean(periodic);
    const field = radiusMap !== undefined ? 'radiusMap' : radiusFn !== undefined ? 'radiusFn' : null;
    if (radiusMap !== undefined && radiusFn !== undefined) throw new TypeError('give radiusMap or radiusFn, not both');
    if (field !== null && radius !== null && radius !== undefined) {
      throw new TypeError(`give radius null with ${field}: the field defines the radius`);
    }
    if (field === null && (radius === null || radius === undefined) && count === undefined) {
      throw new TypeError('Sampler.create needs a radius unless count, radiusMap or radiusFn is given');
    }
    if (radiusFn !== undefined && typeof radiusFn !== 'function') throw new TypeError('radiusFn must be a function (x, y) => radius');
    const r = field !== null || radius === null || radius === undefined ? 1 : Number(radius);
    const ex = api.exports;
    const out = ex.malloc(4);
    let rc;
    try {
      rc = ex.pds_create(out, r, BigInt.asIntN(64, this.seed));
      this.#handle = new Uint32Array(api.memory.buffer, out, 1)[0];
    } finally {
      ex.free(out);
    }
    if (rc < 0) throw errorFor(rc, `pds_create(radius=${r}): ${strerrorOf(api, rc)}`, strerrorOf(api, rc));
    this.#id = registerCallbacks({
      progress: (c, done) => this.#onProgress(c, done),
      radius: (x, y) => this.#onRadius(x, y),
    });
    registry?.register(this, { api, handle: this.#handle, id: this.#id }, this);
    try {
      const [x0, y0, x1, y1] = this.bounds;
      this.#check(ex.pds_set_domain(this.#handle, x0, y0, x1, y1));
      if (this.periodic) this.#check(ex.pds_set_periodic(this.#handle, 1));
      if (count !== undefined) this.#check(ex.pds_set_count(this.#handle, toSize(count, 'count', 0)));
      if (rings !== null) {
        const rc = withCopies(api, [rings.xy, rings.ends],
          (xy, ends) => ex.pds_set_polygon(this.#handle, xy, ends, rings.ends.length));
        this.#check(rc, rings.labels);
        this.bounds = boundingBox(rings.xy);  // the library's rectangle now
      } else if (raster !== null) {
        const { width, height, inside } = raster;
        this.#check(withCopies(api, [inside], (p) => ex.pds_set_mask(this.#handle, width, height, p)));
      }
      if (points !== null) {
        const { n, xy, clearances } = points;
        this.#check(withCopies(api, [xy, clearances], (p, c) => ex.pds_set_fixed(this.#handle, p, c, n)));
      }
      if (radiusMap !== undefined) {
        const values = radiusMapValues(radiusMap);
        this.#check(withCopies(api, [values],
          (p) => ex.pds_set_radius_map(this.#handle, radiusMap.width, radiusMap.height, p)));
      } else if (radiusFn !== undefined) {
        this.#radiusFn = radiusFn;
        this.#check(ex.pdsjs_set_radius_fn(this.#handle, this.#id, Number(rmin), Number(rmax)));
      }
      // undefined: never called, the single-thread process; a number selects the parallel one
      if (threads !== undefined) this.#check(ex.pds_set_threads(this.#handle, threads));
      this.#progress = progress ?? null;
      this.#signal = signal ?? null;
      this.#updateProgress();
    } catch (e) {
      this.dispose();
      throw e;
    }
  }

  // -- callbacks ---------------------------------------------------------------
  #onProgress(count, done) {
    try {
      if (this.#signal?.aborted) return 1;
      if (this.#progress !== null && this.#progress(count, done)) return 1;
      if (this.#now() >= this.#yieldAt) { this.#paused = true; return 1; }
      return 0;
    } catch (e) {
      this.#errors.push(e);  // never unwinds through the library
      return 1;
    }
  }

  #onRadius(x, y) {
    try {
      return Number(this.#radiusFn(x, y));
    } catch (e) {
      this.#errors.push(e);
      return NaN;  // refused by the library before the point is added
    }
  }

  #now() { return typeof performance !== 'undefined' ? performance.now() : Date.now(); }

  #updateProgress() {
    const on = this.#progress !== null || this.#signal !== null || this.#yieldAt !== Infinity;
    this.#check(this.#api.exports.pdsjs_set_progress(this.#handle, on ? this.#id : 0));
  }

  // -- calls -------------------------------------------------------------------
  #h() {
    if (this.#handle === 0) throw new StateError(-3, 'the sampler was disposed', 'disposed');
    if (this.#api.broken) throw this.#trapped(this.#api.broken);
    return this.#handle;
  }

  #trapped(cause) {
    return new InternalError(EINTERNAL, `the WebAssembly module trapped (${cause.message}); `
      + 'it cannot be used further in this realm', strerrorOf(this.#api, EINTERNAL), { cause });
  }

  // A library call; a trap (abort, out of bounds) leaves the module's state
  // unknown, so every later call is refused.
  #call(fn, ...args) {
    this.#errors = [];
    ++this.#calls;
    try {
      return fn(...args);
    } catch (e) {
      if (e instanceof WebAssembly.RuntimeError
          || (WebAssembly.Exception !== undefined && e instanceof WebAssembly.Exception)) {
        this.#api.broken = e;
        throw this.#trapped(e);
      }
      throw e;
    } finally {
      --this.#calls;
    }
  }

  #check(rc, ringLabels = null) {
    if (rc >= 0) return rc;
    const api = this.#api;
    if (this.#errors.length > 0) throw this.#errors[0];
    let message = this.#handle !== 0 ? cString(api, api.exports.pds_errmsg(this.#handle)) : '';
    if (ringLabels !== null) message = withRingLabel(message, ringLabels);
    const strerror = strerrorOf(api, rc);
    const options = rc === ECANCELED && this.#signal?.aborted ? { cause: this.#signal.reason } : undefined;
    throw errorFor(rc, message || strerror, strerror, options);
  }

  /** Add points until maximal (true) or until maxNew were added (false). */
  run(maxNew) {
    const limit = maxNew === undefined ? 0 : toSize(maxNew, 'maxNew', 1);
    const h = this.#h();
    if (this.#signal?.aborted) {
      throw new CanceledError(ECANCELED, 'run(): the AbortSignal was aborted before it started',
        strerrorOf(this.#api, ECANCELED), { cause: this.#signal.reason });
    }
    const ex = this.#api.exports;
    const added = ex.malloc(4);
    try {
      return this.#check(this.#call(ex.pds_run, h, limit, added)) === DONE;
    } finally {
      ex.free(added);
    }
  }

  /**
   * run() in slices of about `sliceMs` (a progress interval at least: 1% of
   * the work), yielding to the event loop between them so that the page stays
   * responsive and the AbortSignal can fire. The same points as run().
   */
  async runAsync({ sliceMs = 30 } = {}) {
    for (;;) {
      this.#yieldAt = this.#now() + sliceMs;
      this.#paused = false;
      this.#updateProgress();
      try {
        return this.run();
      } catch (e) {
        if (!(e instanceof CanceledError && this.#paused && !this.#signal?.aborted)) throw e;
      } finally {
        this.#yieldAt = Infinity;
        if (this.#handle !== 0) this.#updateProgress();
      }
      await new Promise((resolve) => setTimeout(resolve, 0));
    }
  }

  /** Add one point: true if one was added, false if the pattern is maximal. */
  step() {
    return this.#check(this.#call(this.#api.exports.pds_step, this.#h())) === MORE;
  }

  /** Continue at a smaller radius, keeping every point. */
  refine(radius) {
    this.#check(this.#call(this.#api.exports.pds_refine, this.#h(), Number(radius)));
  }

  /** Re-check the pattern from scratch: true if valid and maximal, false if room is left. */
  verify() {
    return this.#check(this.#call(this.#api.exports.pds_verify, this.#h())) === DONE;
  }

  /** The thread count in force (0 given: resolved, to 1 here), 1 until set.
   *  Setting it before the first point selects the parallel process (other
   *  points than the default single-thread process's); once selected it may
   *  change at any time without changing the points; after single-thread
   *  points, StateError. In WebAssembly the count does not change the speed. */
  get threads() { return this.#api.exports.pds_threads(this.#h()); }
  set threads(n) { this.#check(this.#api.exports.pds_set_threads(this.#h(), toThreads(n))); }

  get count() { return this.#api.exports.pds_count(this.#h()); }
  get radius() { return this.#api.exports.pds_radius(this.#h()); }
  get freeArea() {
    const a = this.#call(this.#api.exports.pds_free_area, this.#h());
    if (Number.isNaN(a)) throw errorFor(-2, 'pds_free_area: out of memory', strerrorOf(this.#api, -2));
    return a;
  }

  #copy(name, per, first, count) {
    const h = this.#h();
    const ex = this.#api.exports;
    const total = ex.pds_count(h);
    toSize(first, 'first', 0);
    const n = Math.max(0, Math.min(count ?? total, total - first));
    const out = new Float64Array(n * per);
    if (n === 0) return out;
    const ptr = ex.malloc(n * per * 8);
    if (ptr === 0) throw errorFor(-2, `${name}: no memory for ${n} points`, strerrorOf(this.#api, -2));
    try {
      ex[name](h, first, n, ptr);
      out.set(new Float64Array(this.#api.memory.buffer, ptr, n * per));
    } finally {
      ex.free(ptr);
    }
    return out;
  }

  /** The points in insertion order: x0, y0, x1, y1, ... (a new Float64Array). */
  points(first = 0, count = undefined) { return this.#copy('pds_points', 2, first, count); }
  /** Each point's radius in force (with a field; otherwise all equal radius). */
  radii(first = 0, count = undefined) { return this.#copy('pds_radii', 1, first, count); }

  /** Set or remove (null) the progress callback (count, done) => stop?. */
  setProgress(fn) {
    if (fn !== null && typeof fn !== 'function') throw new TypeError('setProgress needs a function or null');
    this.#h();
    this.#progress = fn;
    this.#updateProgress();
  }

  /** Free the library's sampler now; later calls throw StateError. Idempotent. */
  dispose() {
    if (this.#handle === 0) return;
    if (this.#calls > 0) {
      throw new StateError(-3, 'dispose() from inside a callback of the same sampler', 'busy');
    }
    registry?.unregister(this);
    if (this.#api.broken === null) this.#api.exports.pds_destroy(this.#handle);
    unregisterCallbacks(this.#id);
    this.#handle = 0;
  }

  get disposed() { return this.#handle === 0; }
}

// `using s = await Sampler.create(...)` where the runtime knows Symbol.dispose.
if (typeof Symbol.dispose === 'symbol') {
  Object.defineProperty(Sampler.prototype, Symbol.dispose, {
    value() { this.dispose(); }, writable: true, configurable: true,
  });
}

/** A maximal pattern in one call: the points, x and y interleaved. */
export async function poissonDisk(radius, options = {}) {
  const s = await Sampler.create(radius, options);
  try {
    s.run();
    return s.points();
  } finally {
    s.dispose();
  }
}

/** The library's version, "MAJOR.MINOR.PATCH". */
export async function version() {
  const api = await init();
  return cString(api, api.exports.pds_version_string());
}
