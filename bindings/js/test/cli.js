// The native CLI (build/poissondisk, made by `make`), run for its --format bin
// output: the points the WebAssembly build must reproduce byte for byte.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

export const CLI = process.env.PDS_CLI
  ?? fileURLToPath(new URL('../../../build/poissondisk', import.meta.url));

export function cliPoints(args) {
  if (!existsSync(CLI)) throw new Error(`${CLI} is missing: run make first (or set PDS_CLI)`);
  const out = execFileSync(CLI, [...args, '--format', 'bin', '--no-progress'], { maxBuffer: 1 << 28 });
  return new Uint8Array(out.buffer, out.byteOffset, out.byteLength);
}

// A binary PGM (P5) file of the grey levels, top row first; its path.
export function writePgm(width, height, grey) {
  const dir = mkdtempSync(join(tmpdir(), 'poissondisk-js-'));
  const path = join(dir, 'map.pgm');
  const header = Buffer.from(`P5\n${width} ${height}\n255\n`, 'ascii');
  writeFileSync(path, Buffer.concat([header, Buffer.from(grey)]));
  return path;
}

// A polygon file for --polygon (rings of [x, y], a blank line between rings); its path.
export function writePolygon(rings) {
  const dir = mkdtempSync(join(tmpdir(), 'poissondisk-js-'));
  const path = join(dir, 'polygon.txt');
  writeFileSync(path, rings.map((ring) => ring.map(([x, y]) => `${x} ${y}`).join('\n')).join('\n\n') + '\n');
  return path;
}

export function bytesOf(points) {
  return new Uint8Array(points.buffer, points.byteOffset, points.byteLength);
}
