#!/usr/bin/env python3
"""Turns `cargo bench --bench paths` (target/criterion) into the vector-path tables of
docs/performance.md: the span kernels per path in ns per pixel with their ratios to
the store floor of the same path, what bounds the targets (the set-up alone, the
kernels with the set-up hoisted, the square-root-and-division floor), the triangles per
path against Seiler, Bishop-Weimer and glam, and the targets of docs/performance.md
checked against the numbers of this one run.

    python3 benches/paths_table.py [CRITERION_DIR]
"""
import json, os, sys

root = sys.argv[1] if len(sys.argv) > 1 else "target/criterion"
PATHS = ["baseline", "avx2", "avx512"]


def runs(group):
    """{(function_id, parameter): ns per element} of one criterion group."""
    base = os.path.join(root, group)
    out = {}
    for dirpath, _dirs, files in os.walk(base):
        if "benchmark.json" not in files or os.path.basename(dirpath) != "new":
            continue
        with open(os.path.join(dirpath, "benchmark.json")) as f:
            b = json.load(f)
        with open(os.path.join(dirpath, "estimates.json")) as f:
            mean = json.load(f)["mean"]["point_estimate"]
        elements = (b.get("throughput") or {}).get("Elements") or 1
        out[(b["function_id"], int(b["value_str"]))] = mean / elements
    return out


def split(fid):
    name, _, path = fid.partition("/")
    return name, (path or "-")


spans = runs("paths_f32")
if spans:
    ns = sorted({n for (_, n) in spans})
    names = []
    for fid, _ in spans:
        name, _ = split(fid)
        if name not in names:
            names.append(name)
    order = ["store_floor"] + sorted(n for n in names if n != "store_floor")
    paths = [p for p in PATHS if any(split(f)[1] == p for f, _ in spans)]
    print("\n### Span kernels per vector path: f32, ns per pixel (one span per call, set-up included)\n")
    print("| kernel | path | " + " | ".join(f"n = {n}" for n in ns) + " | ÷ floor, n = 512 | ÷ floor, n = 4096 |")
    print("|---|---|" + "---:|" * (len(ns) + 2))
    for name in order:
        for p in paths:
            key = f"{name}/{p}"
            if (key, ns[0]) not in spans:
                continue
            cells = [f"{spans[(key, n)]:.3f}" for n in ns]
            floor = lambda n: spans[(key, n)] / spans[(f"store_floor/{p}", n)]
            print(f"| {name} | {p} | " + " | ".join(cells) + f" | {floor(512):.2f} | {floor(4096):.2f} |")
    print("\nTargets (long spans, this run):\n")
    for p in paths:
        for k in ["corrected_euler_fast", "gouraud_fast"]:
            r = [spans[(f"{k}/{p}", n)] / spans[(f"store_floor/{p}", n)] for n in (512, 4096)]
            ok = all(x <= 1.5 for x in r)
            print(f"- {p}: {k} ÷ store floor = {r[0]:.2f} (n = 512), {r[1]:.2f} (n = 4096): target ≤ 1.5 {'met' if ok else 'not met'}")
        r = [spans[(f"phong_fast/{p}", n)] / spans[(f"corrected_euler_fast/{p}", n)] for n in (512, 4096)]
        ok = all(x <= 2 for x in r)
        print(f"- {p}: phong_fast ÷ corrected_euler_fast = {r[0]:.2f} (n = 512), {r[1]:.2f} (n = 4096): target ≤ 2 {'met' if ok else 'not met'}")
    if all((f"set_up/{p}", 512) in spans for p in paths):
        print("\nWhat bounds them (this run): the set-up alone and the kernels with the set-up hoisted, "
              "÷ the store floor; Phong's kernel ÷ the square-root-and-division floor, and that floor ÷ corrected Euler:\n")
        print("| path | n | set_up ÷ floor | corrected_euler_kernel ÷ floor | gouraud_kernel ÷ floor "
              "| phong_kernel ÷ sqrt_div_floor | sqrt_div_floor ÷ corrected_euler_fast |")
        print("|---|---:|---:|---:|---:|---:|---:|")
        for p in paths:
            for n in (512, 4096):
                v = lambda k: spans[(f"{k}/{p}", n)]
                fl = v("store_floor")
                print(f"| {p} | {n} | {v('set_up') / fl:.2f} | {v('corrected_euler_kernel') / fl:.2f} "
                      f"| {v('gouraud_kernel') / fl:.2f} | {v('phong_kernel') / v('sqrt_div_floor'):.2f} "
                      f"| {v('sqrt_div_floor') / v('corrected_euler_fast'):.2f} |")

tri = runs("paths_triangle_f32")
if tri:
    sizes = sorted({s for (_, s) in tri})
    print("\n### The paper's polygon per vector path: f32, ns per pixel (legs S)\n")
    print("| method | path | " + " | ".join(f"S = {s}" for s in sizes) + " | ÷ Seiler, S = 8 | ÷ glam Phong, S = 8 |")
    print("|---|---|" + "---:|" * (len(sizes) + 2))
    fids = sorted({f for f, _ in tri}, key=lambda f: (split(f)[1] != "-", split(f)[0], PATHS.index(split(f)[1]) if split(f)[1] in PATHS else -1))
    for f in fids:
        name, p = split(f)
        cells = [f"{tri[(f, s)]:.3f}" for s in sizes]
        print(f"| {name} | {p} | " + " | ".join(cells)
              + f" | {tri[(f, 8)] / tri[('seiler', 8)]:.2f} | {tri[(f, 8)] / tri[('glam_phong', 8)]:.2f} |")
    print("\nTargets (S = 8, this run):\n")
    for p in PATHS:
        ce, ph = f"batched_corrected_euler/{p}", f"batched_phong/{p}"
        if (ce, 8) not in tri:
            continue
        s = tri[(ce, 8)] / tri[("seiler", 8)]
        g = tri[(ce, 8)] / tri[("glam_phong", 8)]
        b = tri[(ph, 8)] / tri[("glam_phong", 8)]
        print(f"- {p}: batched corrected Euler ÷ Seiler = {s:.2f} (target ≤ 0.8: {'met' if s <= 0.8 else 'not met'}), "
              f"÷ glam Phong = {g:.2f} (≤ 0.45: {'met' if g <= 0.45 else 'not met'}); "
              f"batched Phong ÷ glam Phong = {b:.2f} (≤ 0.6: {'met' if b <= 0.6 else 'not met'})")
