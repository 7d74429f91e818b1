// poissondisk: exact maximal Poisson-disk sampling (libpoissondisk in WebAssembly).
export { Sampler, poissonDisk, version } from './sampler.js';
export { radiusMapValues } from './options.js';
export { init } from './wasm.js';
export {
  PoissonDiskError, InvalidArgumentError, OutOfMemoryError, StateError, RangeError,
  InternalError, CanceledError, EINVAL, ENOMEM, ESTATE, ERANGE, EINTERNAL, ECANCELED, DONE, MORE,
} from './errors.js';
