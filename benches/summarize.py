#!/usr/bin/env python3
"""Turns criterion's results (target/criterion) into the Markdown tables of
docs/performance.md: ns per pixel per kernel and n, ratios to glam per-pixel Phong
and to the store floor, the set-up at n = 8, the frame benchmark in pixels/s, the
triangle table, and the table "at the paper's polygon size": every triangle method's
ns per pixel at S = 8, 32, 128 beside its levels from Phong on the 800-polygon torus,
read from `phong-approx compare`'s table2_extended.csv.

    python3 benches/summarize.py [CRITERION_DIR [COMPARE_CSV]]

(defaults: target/criterion and out/compare/table2_extended.csv)."""
import csv, json, os, sys

root = sys.argv[1] if len(sys.argv) > 1 else "target/criterion"
compare_csv = sys.argv[2] if len(sys.argv) > 2 else "out/compare/table2_extended.csv"

def est(path):
    with open(os.path.join(path, "new", "estimates.json")) as f:
        return json.load(f)["mean"]["point_estimate"]

def elements(path):
    with open(os.path.join(path, "new", "benchmark.json")) as f:
        t = json.load(f).get("throughput") or {}
    return t.get("Elements")

def span_table(group):
    base = os.path.join(root, group)
    if not os.path.isdir(base):
        return
    kernels = sorted(k for k in os.listdir(base) if k != "report")
    ns = sorted({int(n) for k in kernels for n in os.listdir(os.path.join(base, k)) if n.isdigit()})
    ns_px = {}
    for k in kernels:
        for n in ns:
            p = os.path.join(base, k, str(n))
            if os.path.isdir(p):
                ns_px[(k, n)] = est(p) / (n + 1)
    print(f"\n### {group}: ns per pixel (one span per call, set-up included)\n")
    print("| kernel | " + " | ".join(f"n = {n}" for n in ns) + " | ÷ glam Phong (n = 512) | ÷ store floor (n = 512) |")
    print("|---|" + "---:|" * (len(ns) + 2))
    order = ["store_floor", "glam_phong"] + [k for k in kernels if k not in ("store_floor", "glam_phong")]
    big = max(ns)
    for k in order:
        if k not in kernels:
            continue
        cells = [f"{ns_px[(k, n)]:.3f}" if (k, n) in ns_px else "" for n in ns]
        r_glam = ns_px[(k, big)] / ns_px[("glam_phong", big)] if ("glam_phong", big) in ns_px else float("nan")
        r_floor = ns_px[(k, big)] / ns_px[("store_floor", big)]
        print(f"| {k} | " + " | ".join(cells) + f" | {r_glam:.2f} | {r_floor:.1f} |")

for g in ("span_f32", "span_f64"):
    span_table(g)

base = os.path.join(root, "setup_f32_n8")
if os.path.isdir(base):
    print("\n### Set-up alone, f32, n = 8\n\n| set-up | ns |\n|---|---:|")
    for k in sorted(os.listdir(base)):
        if k != "report":
            print(f"| {k} | {est(os.path.join(base, k)):.2f} |")

base = os.path.join(root, "frame_torus800_225")
if os.path.isdir(base):
    print("\n### Frame: 800-polygon torus, 225×225, one method (Mpixel/s, visible pixels)\n")
    print("| kernel | single thread | rayon, 8 frames on 2 cores |\n|---|---:|---:|")
    kernels = sorted(os.listdir(os.path.join(base, "single")))
    for k in kernels:
        if k == "report":
            continue
        row = []
        for mode in ("single", "rayon8"):
            p = os.path.join(base, mode, k)
            row.append(f"{elements(p) / est(p) * 1e3:.1f}" if os.path.isdir(p) else "")
        print(f"| {k} | " + " | ".join(row) + " |")

base = os.path.join(root, "triangle_f32")
if os.path.isdir(base):
    methods = sorted(k for k in os.listdir(base) if k != "report")
    sizes = sorted({int(s) for k in methods for s in os.listdir(os.path.join(base, k)) if s.isdigit()})
    print("\n### One triangle with legs S, f32, set-up included: ns per pixel\n")
    print("| method | " + " | ".join(f"S = {s}" for s in sizes) + " | ÷ glam Phong (largest S) |")
    print("|---|" + "---:|" * (len(sizes) + 1))
    per_px = {}
    for k in methods:
        for s in sizes:
            p = os.path.join(base, k, str(s))
            if os.path.isdir(p):
                per_px[(k, s)] = est(p) / elements(p)
    big = max(sizes)
    order = ["glam_phong"] + sorted((k for k in methods if k != "glam_phong"), key=lambda k: per_px.get((k, big), 0))
    for k in order:
        cells = [f"{per_px[(k, s)]:.2f}" if (k, s) in per_px else "" for s in sizes]
        r = per_px[(k, big)] / per_px[("glam_phong", big)] if ("glam_phong", big) in per_px else float("nan")
        print(f"| {k} | " + " | ".join(cells) + f" | {r:.2f} |")

# The bench's triangle methods and the `compare` column whose levels they produce:
# the same values up to rounding (the per-pixel glam Phong normalizes the field at
# every pixel in f32, as phong-field does; the fast_* and span_* rows compute their
# span method's values).
LEVELS_OF = {
    "glam_phong": "phong-field",
    "glam_phong_plain_field": "phong-field",
    "vertex_gouraud": "gouraud-vertex",
    "vertex_angle": "vertex-angle",
    "bishop_weimer": "bishop-weimer-triangle",
    "seiler": "seiler",
    "fast_fence": "gouraud",
    "fast_corrected_euler": "corrected-euler",
    "fast_phong": "phong",
    "fast_phong_rsqrt": "phong",
    "batched_fence": "gouraud-batched",
    "batched_corrected_euler": "corrected-euler-batched",
    "batched_phong": "phong-batched",
    "batched_phong_rsqrt": "phong-batched-rsqrt",
    "stepped_corrected_euler": "corrected-euler-stepped",
    "field_phong": "phong-field",
    "field_phong_rsqrt": "phong-field-rsqrt",
    "span_phong": "phong",
    "span_duff": "duff",
    "span_fence": "gouraud",
    "span_euler": "euler",
    "span_corrected_euler": "corrected-euler",
    "span_angular": "angular",
    "span_spherical": "spherical",
    "span_binary": "binary",
    "span_bishop_weimer": "bishop-weimer",
}

def levels_800():
    """compare's diffuse mean and max levels on the 800-polygon torus, per column."""
    out = {}
    if not os.path.isfile(compare_csv):
        return out
    with open(compare_csv, newline="") as f:
        for row in csv.DictReader(f):
            if row["polygons"] == "800" and row["term"] == "diffuse":
                out[row["method"]] = (float(row["mean"]), int(row["max"]))
    return out

base = os.path.join(root, "triangle_f32")
if os.path.isdir(base):
    lv = levels_800()
    per_px = {}
    for k in os.listdir(base):
        if k == "report":
            continue
        for sz in os.listdir(os.path.join(base, k)):
            p = os.path.join(base, k, sz)
            if sz.isdigit() and os.path.isdir(p):
                per_px[(k, int(sz))] = est(p) / elements(p)
    sizes = sorted({sz for _, sz in per_px})
    small = min(sizes)
    print(f"\n### At the paper's polygon size: ns per pixel on one triangle (f32, set-up included), "
          f"levels from Phong on the 800-polygon torus\n")
    print("| method | " + " | ".join(f"S = {sz}" for sz in sizes)
          + f" | ÷ glam Phong (S = {small}) | ÷ Seiler (S = {small}) | mean levels | max levels | as `compare` column |")
    print("|---|" + "---:|" * (len(sizes) + 4) + "---|")
    glam, seiler = per_px.get(("glam_phong", small)), per_px.get(("seiler", small))
    methods = sorted({k for k, _ in per_px}, key=lambda k: per_px.get((k, small), 0))
    for k in methods:
        cells = [f"{per_px[(k, sz)]:.2f}" if (k, sz) in per_px else "" for sz in sizes]
        t = per_px.get((k, small))
        rg = f"{t / glam:.2f}" if t and glam else ""
        rs = f"{t / seiler:.2f}" if t and seiler else ""
        col = LEVELS_OF.get(k, "")
        mean, mx = (f"{lv[col][0]:.3f}", str(lv[col][1])) if col in lv else ("", "")
        print(f"| {k} | " + " | ".join(cells) + f" | {rg} | {rs} | {mean} | {mx} | {col} |")

base = os.path.join(root, "specular_span_f32")
if os.path.isdir(base):
    print("\n### The specular span, f32, s = 32 (benches/specular.rs): ns per span, set-up included\n")
    rows = sorted(k for k in os.listdir(base) if k != "report")
    ns = sorted({int(n) for k in rows for n in os.listdir(os.path.join(base, k)) if n.isdigit()})
    print("| row | " + " | ".join(f"n = {n}" for n in ns) + " | " + " | ".join(f"÷ corrected Euler then power (n = {n})" for n in ns) + " |")
    print("|---|" + "---:|" * (2 * len(ns)))
    ref = {n: est(os.path.join(base, "corrected_euler_then_power", str(n))) for n in ns}
    for k in rows:
        t = {n: est(os.path.join(base, k, str(n))) for n in ns if os.path.isdir(os.path.join(base, k, str(n)))}
        print(f"| {k} | " + " | ".join(f"{t[n]:.0f}" if n in t else "" for n in ns) + " | "
              + " | ".join((f"{t[n] / ref[n]:.0f}" if t[n] / ref[n] >= 10 else f"{t[n] / ref[n]:.2f}") if n in t else "" for n in ns) + " |")

base = os.path.join(root, "specular_paths_f32")
if os.path.isdir(base):
    print("\n### The fast kernels' specular span per vector path, f32, s = 32 (benches/specular.rs): ns per span, set-up included\n")
    paths = ["baseline", "avx2", "avx512"]
    found = []
    for d in sorted(os.listdir(base)):
        for p in paths:
            if d.endswith("_" + p):
                found.append((d[: -len(p) - 1], p, d))
    ns = sorted({int(n) for _, _, d in found for n in os.listdir(os.path.join(base, d)) if n.isdigit()})
    print("| row | path | " + " | ".join(f"n = {n}" for n in ns) + " | "
          + " | ".join(f"÷ corrected Euler then power (n = {n})" for n in ns) + " |")
    print("|---|---|" + "---:|" * (2 * len(ns)))
    order = {p: i for i, p in enumerate(paths)}
    for k, p, d in sorted(found, key=lambda r: (r[0], order[r[1]])):
        ref = {n: est(os.path.join(base, f"corrected_euler_fast_then_power_{p}", str(n))) for n in ns}
        t = {n: est(os.path.join(base, d, str(n))) for n in ns if os.path.isdir(os.path.join(base, d, str(n)))}
        print(f"| {k} | {p} | " + " | ".join(f"{t[n]:.0f}" if n in t else "" for n in ns) + " | "
              + " | ".join(f"{t[n] / ref[n]:.2f}" if n in t else "" for n in ns) + " |")
