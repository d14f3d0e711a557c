// Writes FILE.gz (gzip -9) and FILE.br (brotli, quality 11) beside each file given, so that a
// static server that serves pre-compressed files sends the smaller one, and prints the sizes.
// Node's own zlib: nothing to install. Run: node .ci/web/compress.mjs FILE...
import fs from "node:fs";
import zlib from "node:zlib";

for (const file of process.argv.slice(2)) {
  const raw = fs.readFileSync(file);
  const gz = zlib.gzipSync(raw, { level: 9 });
  const br = zlib.brotliCompressSync(raw, {
    params: {
      [zlib.constants.BROTLI_PARAM_QUALITY]: 11,
      [zlib.constants.BROTLI_PARAM_LGWIN]: 24,
      [zlib.constants.BROTLI_PARAM_SIZE_HINT]: raw.length,
    },
  });
  for (const [suffix, bytes] of [[".gz", gz], [".br", br]]) {
    // Beside the target, then renamed into place: never a half-written file.
    fs.writeFileSync(`${file}${suffix}.tmp`, bytes);
    fs.renameSync(`${file}${suffix}.tmp`, `${file}${suffix}`);
  }
  console.log(`${file}: ${raw.length} bytes, ${gz.length} gzipped, ${br.length} with brotli`);
}
