// The errors: one class per PDS_E* code, all under PoissonDiskError, each
// carrying the library's message (pds_errmsg, which starts with the name of
// the C function) and the code's generic text (pds_strerror).

export const EINVAL = -1;
export const ENOMEM = -2;
export const ESTATE = -3;
export const ERANGE = -4;
export const EINTERNAL = -5;
export const ECANCELED = -6;
export const DONE = 0;
export const MORE = 1;

export class PoissonDiskError extends Error {
  constructor(code, message, strerror, options) {
    const text = strerror && !message.includes(strerror)
      ? `${message} [${strerror}, code ${code}]` : `${message} [code ${code}]`;
    super(text, options);
    this.name = new.target.name;
    this.code = code;
    this.libraryMessage = message;
    this.strerror = strerror;
  }
}

/** PDS_EINVAL: an argument is invalid (NaN, infinite, out of its range). */
export class InvalidArgumentError extends PoissonDiskError {}
/** PDS_ENOMEM: memory could not be allocated (wasm32 holds at most 4 GiB). */
export class OutOfMemoryError extends PoissonDiskError {}
/** PDS_ESTATE: not allowed now (a change from inside a callback, refine in count mode). */
export class StateError extends PoissonDiskError {}
/** PDS_ERANGE: the radius does not suit the domain (precision, index space, torus). */
export class RangeError extends PoissonDiskError {}
/** PDS_EINTERNAL: an internal check failed (a bug), or the WebAssembly module trapped. */
export class InternalError extends PoissonDiskError {}
/** PDS_ECANCELED: the progress callback or the AbortSignal stopped run(). */
export class CanceledError extends PoissonDiskError {}

const BY_CODE = new Map([
  [EINVAL, InvalidArgumentError],
  [ENOMEM, OutOfMemoryError],
  [ESTATE, StateError],
  [ERANGE, RangeError],
  [EINTERNAL, InternalError],
  [ECANCELED, CanceledError],
]);

export function errorFor(code, message, strerror, options) {
  const Class = BY_CODE.get(code) ?? PoissonDiskError;
  return new Class(code, message, strerror, options);
}
