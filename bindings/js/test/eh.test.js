// The C++ exception runtime of the WebAssembly build (wasm/cxx_eh.cpp), on
// its own cases (wasm/test/eh_cases.cpp, built by make as build/wasm/eh_cases.wasm).
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

const path = process.env.PDS_EH_CASES
  ?? new URL('../../../build/wasm/eh_cases.wasm', import.meta.url);

async function load() {
  const module = await WebAssembly.compile(readFileSync(path));
  const imports = {};
  for (const { module: m, name } of WebAssembly.Module.imports(module)) {
    (imports[m] ??= {})[name] = () => { throw new Error(`unexpected import ${m}.${name}`); };
  }
  const instance = await WebAssembly.instantiate(module, imports);
  instance.exports._initialize();
  return instance.exports;
}

test('each thrown type is caught by its clause (exact, derived-to-base, int, none)', async () => {
  const ex = await load();
  assert.equal(ex.catch_kind(0), 0);
  assert.equal(ex.catch_kind(1), 1, 'std::bad_alloc');
  assert.equal(ex.catch_kind(2), 2, 'a class derived from std::runtime_error');
  assert.equal(ex.catch_kind(3), 3, 'std::logic_error as std::exception');
  assert.equal(ex.catch_kind(4), 4, 'an int');
  assert.equal(ex.destroyed_count(), 5, 'the guard was destroyed in each call, also while unwinding');
});

test('rethrow, nested handlers, destructors while unwinding; thousands in a row', async () => {
  const ex = await load();
  assert.equal(ex.rethrow_outer(), 1);
  assert.equal(ex.nested(), 1);
  for (let i = 0; i < 10000; ++i) assert.equal(ex.catch_kind(1 + (i % 4)), 1 + (i % 4));
  assert.equal(ex.rethrow_outer(), 1, 'still sound after many');
});

test('operator new throws std::bad_alloc when the 4 GiB memory is exhausted', async () => {
  const ex = await load();
  assert.equal(ex.alloc_fails(5000), 1);
  assert.equal(ex.catch_kind(1), 1, 'usable afterwards');
});
