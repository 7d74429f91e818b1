// Type declarations of the poissondisk package.

/** A radius map over the domain: radii in user units, row 0 along y0, or the
 *  grey levels of an image (top row first, along y1), linear from rmin (0,
 *  black) to rmax (maxval, white), as the CLI's --radius-map. */
export type RadiusMap =
  | { width: number; height: number; radii: ArrayLike<number> }
  | { width: number; height: number; grey: ArrayLike<number>; rmin: number; rmax: number; maxval?: number };

/** A ring: [x, y] pairs, or flat numbers x0, y0, x1, y1, ... (either way round; closing vertex optional). */
export type Ring = ArrayLike<readonly [number, number] | ArrayLike<number>> | ArrayLike<number>;

/** GeoJSON geometries and features that enclose an area (positions may carry a z, dropped). */
export type GeoJSONArea =
  | { type: 'Polygon'; coordinates: ArrayLike<ArrayLike<ArrayLike<number>>> }
  | { type: 'MultiPolygon'; coordinates: ArrayLike<ArrayLike<ArrayLike<ArrayLike<number>>>> }
  | { type: 'GeometryCollection'; geometries: ArrayLike<GeoJSONArea> }
  | { type: 'Feature'; geometry: GeoJSONArea; properties?: unknown }
  | { type: 'FeatureCollection'; features: ArrayLike<{ type: 'Feature'; geometry: GeoJSONArea }> };

/** An image mask, TOP row first (along y1), each value a boolean or 0/1: rows, or row-major values. */
export type Mask =
  | ArrayLike<ArrayLike<boolean | number>>
  | { width: number; height: number; inside: ArrayLike<boolean | number> };

/** Fixed points: flat x, y numbers (such as points() returns), [x, y] or [x, y, clearance] rows
 *  (mixed: an [x, y] row has clearance 0), or { points, clearances }; a clearance 0 means the
 *  radius in force there. */
export type FixedPoints =
  | ArrayLike<number>
  | ArrayLike<readonly [number, number] | readonly [number, number, number]>
  | { points: ArrayLike<number> | ArrayLike<readonly [number, number]>; clearances?: ArrayLike<number> };

export interface SamplerOptions {
  /** 0 <= seed < 2**64 (a BigInt beyond 2**53); random when omitted (read it back from `.seed`). */
  seed?: number | bigint;
  /** [x0, y0, x1, y1]; the unit square by default. */
  bounds?: [number, number, number, number] | ArrayLike<number>;
  /** Sample the rectangle as a flat torus: the pattern tiles the plane. */
  periodic?: boolean;
  /** The domain is a polygon: rings (even-odd rule: holes and outer rings alike, either way round,
   *  rings that cross too) or GeoJSON; its bounding box becomes `bounds` (give no bounds). Not with periodic. */
  polygon?: ArrayLike<Ring> | Ring | GeoJSONArea;
  /** The domain is the union of a mask's inside pixels spread over `bounds`, top row along y1. */
  mask?: Mask;
  /** Points already there: new points keep their clearance; they count for coverage and are not returned. */
  fixed?: FixedPoints;
  /** Exactly this many points; the library chooses the radius (radius may then be null). */
  count?: number;
  /** A variable radius from a map (radius null). */
  radiusMap?: RadiusMap;
  /** A variable radius from a function, with the bounds of its values (radius null). Called once
   *  per point; with threads, when its dart is accepted, up to one epoch of darts before run()
   *  returns the point. */
  radiusFn?: (x: number, y: number) => number;
  rmin?: number;
  rmax?: number;
  /** Called between points by run(): `done` in [0, 1]; return true to stop it (CanceledError). */
  progress?: (count: number, done: number) => boolean | void;
  /** Checked at each progress call and before run(): aborting stops run() with CanceledError. */
  signal?: AbortSignal;
  /** Omitted (the default): the single-thread process. A number, 0 to 1024 (0: one per core),
   *  selects the parallel process on that many threads, whose points do not depend on the count
   *  but differ from the default's. The WebAssembly build has one thread: no change of speed. */
  threads?: number;
}

export class Sampler {
  private constructor();
  /** A sampler; `radius` may be a function (x, y) => r (then give rmin and rmax). */
  static create(radius: number | null | ((x: number, y: number) => number),
    options?: SamplerOptions): Promise<Sampler>;
  readonly seed: bigint;
  /** [x0, y0, x1, y1]: as given, or the polygon's bounding box. */
  readonly bounds: number[];
  readonly periodic: boolean;
  /** The thread count in force, 1 until set (see SamplerOptions.threads). Setting it before the
   *  first point selects the parallel process, then at any time; StateError once the
   *  single-thread process has made points. */
  threads: number;
  /** Add points until maximal (true) or until maxNew were added (false). Synchronous. */
  run(maxNew?: number): boolean;
  /** run() in slices of about sliceMs, yielding to the event loop between them: the same points. */
  runAsync(options?: { sliceMs?: number }): Promise<boolean>;
  /** Add one point: true if one was added, false if the pattern is maximal. */
  step(): boolean;
  /** Continue at a smaller radius, keeping every point. */
  refine(radius: number): void;
  /** Re-check from scratch: true if valid and maximal, false if valid with room left. */
  verify(): boolean;
  /** The points in insertion order, x and y interleaved (a new array). */
  points(first?: number, count?: number): Float64Array;
  /** Each point's radius in force. */
  radii(first?: number, count?: number): Float64Array;
  setProgress(fn: ((count: number, done: number) => boolean | void) | null): void;
  readonly count: number;
  /** The current radius (the largest in force with a field). */
  readonly radius: number;
  /** Area where a point could still go; 0 once maximal. */
  readonly freeArea: number;
  /** Free the sampler's memory now; later calls throw StateError. */
  dispose(): void;
  readonly disposed: boolean;
}

/** A maximal pattern in one call: the points, x and y interleaved. */
export function poissonDisk(radius: number | null | ((x: number, y: number) => number),
  options?: SamplerOptions): Promise<Float64Array>;
/** The library's version, "MAJOR.MINOR.PATCH". */
export function version(): Promise<string>;
/** The radii a RadiusMap stands for, row 0 along y0 (as pds_set_radius_map takes them). */
export function radiusMapValues(map: RadiusMap): Float64Array;
/** Load the module from elsewhere (a URL, bytes or a WebAssembly.Module), e.g. for bundlers. */
export function init(source?: URL | string | BufferSource | WebAssembly.Module): Promise<unknown>;

export class PoissonDiskError extends Error {
  /** The negative PDS_E* code. */
  readonly code: number;
  /** The library's own message (pds_errmsg), starting with the C function's name. */
  readonly libraryMessage: string;
  /** The code's generic text (pds_strerror). */
  readonly strerror: string;
}
export class InvalidArgumentError extends PoissonDiskError {}
export class OutOfMemoryError extends PoissonDiskError {}
export class StateError extends PoissonDiskError {}
export class RangeError extends PoissonDiskError {}
export class InternalError extends PoissonDiskError {}
export class CanceledError extends PoissonDiskError {}

export const EINVAL: -1;
export const ENOMEM: -2;
export const ESTATE: -3;
export const ERANGE: -4;
export const EINTERNAL: -5;
export const ECANCELED: -6;
export const DONE: 0;
export const MORE: 1;
