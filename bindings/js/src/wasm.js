// The WebAssembly module: loading it (fs in Node, fetch in browsers and
// workers), the few WASI imports it links against, and the two imported
// callbacks (progress, radius function) that route to JavaScript functions.
//
// WASI: the library never reads or writes files. clock_time_get serves
// std::chrono::steady_clock (the progress callback's "a second has passed");
// fd_write, fd_seek and fd_close come with wasi-libc's stdio and answer EBADF.

const WASI_EBADF = 8;

let loading = null;     // Promise<Api>
const callbacks = new Map();  // id -> { progress(count, done), radius(x, y) }
let nextId = 1;

export function registerCallbacks(entry) {
  const id = nextId++;
  callbacks.set(id, entry);
  return id;
}
export function unregisterCallbacks(id) { callbacks.delete(id); }

async function compileFrom(source) {
  if (source instanceof WebAssembly.Module) return source;
  if (source instanceof ArrayBuffer || ArrayBuffer.isView(source)) return WebAssembly.compile(source);
  const url = source instanceof URL ? source : new URL(String(source), import.meta.url);
  if (url.protocol === 'file:') {
    const { readFile } = await import('node:fs/promises');
    return WebAssembly.compile(await readFile(url));
  }
  const response = await fetch(url);
  if (!response.ok) throw new Error(`poissondisk: cannot load ${url}: HTTP ${response.status}`);
  return WebAssembly.compile(await response.arrayBuffer());
}

function instantiate(module) {
  let memory = null;
  const now = typeof performance !== 'undefined' ? () => performance.now() : () => Date.now();
  const imports = {
    wasi_snapshot_preview1: {
      clock_time_get(clockId, _precision, out) {
        const ms = clockId === 0 ? Date.now() : now();
        new DataView(memory.buffer).setBigUint64(out, BigInt(Math.round(ms * 1e6)), true);
        return 0;
      },
      fd_write: () => WASI_EBADF,
      fd_seek: () => WASI_EBADF,
      fd_close: () => WASI_EBADF,
    },
    poissondisk: {
      progress(id, count, done) { return callbacks.get(id)?.progress(count, done) ?? 0; },
      radius(id, x, y) { return callbacks.get(id)?.radius(x, y) ?? NaN; },
    },
  };
  return WebAssembly.instantiate(module, imports).then((instance) => {
    memory = instance.exports.memory;
    instance.exports._initialize();
    return { exports: instance.exports, memory, broken: null };
  });
}

/**
 * Load the module once per JavaScript realm (each worker has its own).
 * `source`: a URL, bytes or a compiled WebAssembly.Module, for bundlers
 * that move the .wasm; by default ../poissondisk.wasm next to this file.
 */
export function init(source) {
  if (loading === null || source !== undefined) {
    const from = source ?? new URL('../poissondisk.wasm', import.meta.url);
    loading = compileFrom(from).then(instantiate);
    loading.catch(() => { loading = null; });  // a later call may retry
  }
  return loading;
}
