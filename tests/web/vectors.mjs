// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The WebAssembly build of libpgloss held to the shared vectors under Node: the command line of
// vectors-check.mjs (which says what is checked; the browser test runs the same checks in Chromium).
//   node tests/web/vectors.mjs build-web/wasm/pgloss.wasm
import { readFileSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { resolve, dirname } from 'node:path';
import { loadPgloss } from '../../web/picker/pgloss-wasm.js';
import { ALL_FILES, checkVectors } from './vectors-check.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const wasmPath = resolve(process.argv[2] ?? `${root}/build-web/wasm/pgloss.wasm`);
const pg = await loadPgloss(pathToFileURL(wasmPath));
const docs = Object.fromEntries(ALL_FILES.map((f) => [f, JSON.parse(readFileSync(`${root}/tests/vectors/${f}.json`, 'utf8'))]));
const { failed, summary } = checkVectors(pg, docs);
console.log(summary);
process.exit(failed ? 1 : 0);
