// Checks the math of the rustdoc pages built from docs/{derivations,errata,float}.md in
// headless Chromium; run by docs/check-math.sh, which builds the docs with a local KaTeX.
//
//   node docs/check-math.mjs <target/doc> <katex dist dir> <node_modules> <screenshot dir>
//
// Serves the docs (and KaTeX under /katex/) on 127.0.0.1, opens each page and fails if
// KaTeX reports an error (`.katex-error`), if a `$` is left in the text outside code and
// formulas, or if the TeX of the formulas on the page (KaTeX keeps it in a MathML
// annotation) is not, in order, the TeX of the math segments of the Markdown source:
// that is what proves rustdoc's Markdown left the escaped math intact.
import { createServer } from "node:http";
import { readFileSync, existsSync, mkdirSync, statSync } from "node:fs";
import { createRequire } from "node:module";
import { extname, join, normalize } from "node:path";

// A crash (no browser, a page that does not load) is "could not check" (2), not "the
// math is wrong" (1).
for (const ev of ["uncaughtException", "unhandledRejection"]) {
  process.on(ev, (e) => { console.error(`math check could not run: ${e?.stack ?? e}`); process.exit(2); });
}
const [docDir, katexDir, modules, shots] = process.argv.slice(2);
const { chromium } = createRequire(join(modules, "x.js"))("playwright-core");
const pages = ["derivations", "errata", "float"];

// The math segments of a Markdown text, found independently of build/math.rs: fenced
// code and code spans removed, then `$$…$$` and `$…$` (GitHub's rules, simplified).
// Inline math opens at a `$` before a non-blank and closes at the next unescaped `$`
// that is not after a blank nor before a digit, within the paragraph; its last character
// may be an escaped one (`$t \in \{0, 1\}$`, `$a\,$`).
function segments(md) {
  md = md.replace(/^[ \t]*(```|~~~)[\s\S]*?^[ \t]*\1[^\n]*$/gm, "");
  md = md.replace(/(`+)[\s\S]*?[^`]\1(?!`)/g, "");
  const re = /\$\$([\s\S]+?)\$\$|\$(?=[^\s$])((?:\\[\s\S]|[^$\\\n]|\n(?![ \t]*\n))*?(?:\\\S|[^\s\\]))\$(?!\d)/g;
  return [...md.matchAll(re)].map((m) => ({ display: m[1] !== undefined, tex: m[1] ?? m[2] }));
}
const norm = (s) => s.replace(/\s+/g, " ").trim();

const types = { ".html": "text/html", ".js": "text/javascript", ".css": "text/css",
  ".woff2": "font/woff2", ".woff": "font/woff", ".ttf": "font/ttf", ".svg": "image/svg+xml" };
const server = createServer((req, res) => {
  const url = decodeURIComponent(new URL(req.url, "http://x").pathname);
  const [root, rel] = url.startsWith("/katex/") ? [katexDir, url.slice(7)] : [docDir, url];
  let file = normalize(join(root, rel));
  if (existsSync(file) && statSync(file).isDirectory()) file = join(file, "index.html");
  if (!file.startsWith(normalize(root)) || !existsSync(file)) {
    res.writeHead(404).end();
    return;
  }
  res.writeHead(200, { "content-type": types[extname(file)] ?? "application/octet-stream" });
  res.end(readFileSync(file));
});
await new Promise((r) => server.listen(0, "127.0.0.1", r));
const base = `http://127.0.0.1:${server.address().port}`;

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
  args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync"],
});
mkdirSync(shots, { recursive: true });
let failed = false;
const fail = (msg) => { failed = true; console.log(`  FAIL ${msg}`); };

for (const name of pages) {
  const page = await browser.newPage({ viewport: { width: 1200, height: 900 } });
  const messages = [];
  page.on("console", (m) => { if (m.type() !== "log" && !m.text().startsWith("A preload for")) messages.push(`${m.type()}: ${m.text()}`); });
  page.on("pageerror", (e) => messages.push(`pageerror: ${e.message}`));
  await page.goto(`${base}/phong_approx/${name}/index.html`, { waitUntil: "load" });
  await page.evaluate(() => document.fonts.ready);
  const r = await page.evaluate(() => {
    const root = document.getElementById("main-content");
    const formulas = [...root.querySelectorAll(".katex")].map((k) => ({
      display: !!k.closest(".katex-display"),
      tex: k.querySelector('annotation[encoding="application/x-tex"]')?.textContent ?? "",
    }));
    const errors = [...root.querySelectorAll(".katex-error")].map(
      (e) => `${e.getAttribute("title")} in ${e.textContent.slice(0, 80)}`);
    const raw = [];
    const walk = document.createTreeWalker(root, NodeFilter.SHOW_TEXT);
    for (let n; (n = walk.nextNode());) {
      if (n.textContent.includes("$") && !n.parentElement.closest("code, pre, .katex, .katex-error"))
        raw.push(n.textContent.trim().slice(0, 100));
    }
    return { formulas, errors, raw };
  });
  const want = segments(readFileSync(new URL(`./${name}.md`, import.meta.url), "utf8"));
  const display = r.formulas.filter((f) => f.display).length;
  console.log(`${name}: ${r.formulas.length} formulas rendered (${display} display), ` +
    `${want.length} math segments in docs/${name}.md (${want.filter((w) => w.display).length} display)`);
  for (const e of r.errors) fail(`KaTeX error: ${e}`);
  for (const t of r.raw) fail(`raw $ left in the text: ${t}`);
  if (r.formulas.length !== want.length) fail(`${r.formulas.length} formulas for ${want.length} segments`);
  let diffs = 0;
  for (let i = 0; i < Math.min(r.formulas.length, want.length) && diffs < 5; i++) {
    const got = r.formulas[i], exp = want[i];
    if (norm(got.tex) !== norm(exp.tex) || got.display !== exp.display) {
      diffs++;
      fail(`formula ${i + 1}: the page has ${JSON.stringify(got)}, the source ${JSON.stringify(exp)}`);
    }
  }
  for (const m of messages) console.log(`  console ${m}`);
  // Screenshots to look at: the first table and the first display formula of each page.
  const table = page.locator("#main-content .docblock table").first();
  if (await table.count()) await table.screenshot({ path: join(shots, `${name}-table.png`) });
  const disp = page.locator("#main-content .katex-display").first();
  if (await disp.count()) {
    await disp.locator("xpath=..").screenshot({ path: join(shots, `${name}-display.png`) });
  }
  if (name === "derivations") {
    // §1 of the derivations, from its heading to the end of the notation table.
    const clip = await page.evaluate(() => {
      const h = document.getElementById("1-conventions");
      const t = h && document.querySelector("#main-content .docblock table");
      if (!t) return null;
      const a = h.getBoundingClientRect(), b = t.getBoundingClientRect();
      return { x: Math.min(a.left, b.left) - 8, y: a.top + scrollY - 8,
        width: Math.max(a.right, b.right) - Math.min(a.left, b.left) + 16,
        height: b.bottom - a.top + 16 };
    });
    if (clip) await page.screenshot({ path: join(shots, "derivations-conventions.png"), clip, fullPage: true });
  }
  await page.close();
}
await browser.close();
server.close();
console.log(failed ? "math check FAILED" : "math check passed");
process.exit(failed ? 1 : 0);
