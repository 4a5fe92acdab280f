// Reads Arrow IPC files ("feather v2") with arrow-js and prints, per file, the row count and
// each column's type, null count, first values and last value. An interoperability check of
// hdprior's feather writer, run by hand; not part of CI.
//
// arrow-js (apache-arrow >= 21) reads compressed record batches only through codecs the caller
// registers; it ships none. This script registers lz4js (LZ4_FRAME) and fzstd (ZSTD).
//
// Setup, outside the repository:
//   mkdir -p /tmp/arrowjs && cd /tmp/arrowjs && npm init -y && npm install apache-arrow lz4js fzstd
// Run (from that folder, or set ARROW_JS_DIR to it):
//   node /path/to/hdprior/tests/interop/read_with_arrow_js.mjs FILE.feather [FILE.feather ...]
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';

const require = createRequire(path.join(process.env.ARROW_JS_DIR ?? process.cwd(), 'index.js'));
const arrow = require('apache-arrow');
const lz4 = require('lz4js');
const fzstd = require('fzstd');

// arrow-js views decoded buffers as typed arrays in place, so they must start 8-byte aligned;
// fzstd returns views at odd offsets into its own buffers, hence the copy.
const aligned = (bytes) => (bytes.byteOffset % 8 === 0 ? bytes : bytes.slice());
arrow.compressionRegistry.set(arrow.CompressionType.LZ4_FRAME, { decode: (bytes) => aligned(lz4.decompress(bytes)) });
arrow.compressionRegistry.set(arrow.CompressionType.ZSTD, { decode: (bytes) => aligned(fzstd.decompress(bytes)) });

const arrowDir = path.dirname(require.resolve('apache-arrow'));  // package.json is not exported
const version = JSON.parse(readFileSync(path.join(arrowDir, 'package.json'), 'utf8')).version;
const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: node read_with_arrow_js.mjs FILE.feather...');
  process.exit(2);
}
let failed = false;
for (const file of files) {
  try {
    const table = arrow.tableFromIPC(readFileSync(file));
    console.log(`${path.basename(file)}: ${table.numRows} rows, ${table.batches.length} batches (apache-arrow ${version})`);
    for (const field of table.schema.fields) {
      const column = table.getChild(field.name);
      const first = [];
      for (let i = 0; i < Math.min(3, column.length); ++i) first.push(String(column.get(i)));
      const last = column.length > 0 ? String(column.get(column.length - 1)) : '-';
      console.log(`  ${field.name}: ${field.type} nulls=${column.nullCount} first=[${first.join(', ')}] last=${last}`);
    }
  } catch (error) {
    failed = true;
    console.log(`${path.basename(file)}: FAILED ${error.message}`);
  }
}
process.exit(failed ? 1 : 0);
