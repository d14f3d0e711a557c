// A plain static server for a built site on 127.0.0.1, for the measuring scripts
// (frame-time.mjs, real-time.mjs); the browser test keeps its own, which also serves the
// pre-compressed files and counts the bytes.
import http from "node:http";
import fs from "node:fs";
import path from "node:path";

const types = { ".html": "text/html", ".js": "text/javascript", ".wasm": "application/wasm" };

// Serves `site` on a free port: resolves to its address and the server (to close).
export const serve = (site) => new Promise((resolve) => {
  const server = http.createServer((req, res) => {
    let f = path.join(site, decodeURIComponent(new URL(req.url, "http://x").pathname));
    if (f.endsWith("/")) f = path.join(f, "index.html");
    if (!fs.existsSync(f)) { res.writeHead(404).end(); return; }
    res.writeHead(200, { "content-type": types[path.extname(f)] ?? "application/octet-stream" });
    fs.createReadStream(f).pipe(res);
  });
  server.listen(0, "127.0.0.1", () => resolve({ url: `http://127.0.0.1:${server.address().port}/`, server }));
});
