#!/usr/bin/env python3
"""The table of tools/gpu/measure.sh, from what it left in OUT:

    summarise.py OUT REFERENCES

OUT/gl.log (a one-frame demo: its first line names the GL context),
OUT/checks/<stage>.log and .rc (`raylab check --solution --against`),
OUT/bench-<track>-<size>/bench.csv or fur.csv (`raylab bench`). Prints
Markdown; a stage whose check failed, or a bench that left no CSV, shows
FAIL in its row."""
import csv
import math
import os
import platform
import re
import sys
import time


def gl_string(out):
    with open(os.path.join(out, "gl.log"), encoding="utf-8", errors="replace") as f:
        first = f.readline().strip()
    # "... egl backend, OpenGL 4.5 (Core Profile) Mesa ... on llvmpipe (...)"
    m = re.search(r"backend, (.*)$", first)
    return m.group(1) if m else first


def check_rows(out):
    rows = []
    folder = os.path.join(out, "checks")
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".log"):
            continue
        stage = name[:-4]
        with open(os.path.join(folder, name), encoding="utf-8", errors="replace") as f:
            lines = f.read().splitlines()
        with open(os.path.join(folder, stage + ".rc"), encoding="utf-8") as f:
            rc = int(f.read().strip() or 1)
        views = [l for l in lines if re.match(r"\s+(PASS|FAIL) ", l) and "cases" not in l]
        functions = [l for l in lines if re.match(r"\s+(PASS|FAIL) ", l) and "cases" in l]
        shares = [float(m.group(1)) for l in views for m in [re.search(r"([0-9.]+)% of pixels", l)] if m]
        passed = lambda ls: sum(1 for l in ls if l.strip().startswith("PASS"))
        failing = [l.split()[1] for l in views + functions if l.strip().startswith("FAIL")]
        result = "pass" if rc == 0 else "FAIL"
        note = ""
        if rc != 0:
            note = ", ".join(failing) if failing else (lines[-1].strip() if lines else "no output")
        rows.append((stage, result, f"{passed(views)}/{len(views)}",
                     f"{passed(functions)}/{len(functions)}",
                     f"{max(shares):.2f}%" if shares else "n/a", note))
    return rows


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def ms(value):
    try:
        v = float(value)
    except (TypeError, ValueError):
        return None
    return None if math.isnan(v) else v


def ray_lever(lever):
    # As bench_rows.cpp: tree-all, lbuf and eye change how rays find objects, not which.
    return "+".join(p for p in lever.split("+") if p and p not in ("tree-all", "lbuf", "eye"))


def setting_name(r):
    parts = [r["lever"] or "baseline"]
    if r["specialized"] == "1":
        parts.append("specialised")
    if r["bvh"] == "0":
        parts.append("linear search")
    if r["numerics"] != "robust":
        parts.append(r["numerics"] + " numerics")
    if r["torus_solver"] != "robust":
        parts.append("torus " + r["torus_solver"])
    return ", ".join(parts)


def x_embree(rows, r):
    """R's frame time over Embree's casting the same rays (bench_markdown.cpp's pairing)."""
    e = next((e for e in rows if e["engine"] == "embree" and e["lever"] == ray_lever(r["lever"])
              and e["width"] == r["width"] and e["height"] == r["height"]
              and e["depth"] == r["depth"] and e["shadows"] == r["shadows"]), None)
    return f"{ms(r['frame_ms']) / ms(e['frame_ms']):.2f}" if e and ms(e["frame_ms"]) else "n/a"


def raytrace_rows(rows, size):
    out = []
    for scene in sorted({r["scene"] for r in rows}):
        mine = [r for r in rows if r["scene"] == scene]
        glsl = [r for r in mine if r["engine"] == "glsl" and r["depth"] == "8" and r["shadows"] == "1"
                and ms(r["frame_ms"]) is not None]
        if not glsl:
            continue
        big = max(int(r["width"]) * int(r["height"]) for r in glsl)
        glsl = [r for r in glsl if int(r["width"]) * int(r["height"]) == big]
        base = next((r for r in glsl if r["lever"] == "" and r["bvh"] == "1" and r["specialized"] == "0"
                     and r["numerics"] == "robust" and r["torus_solver"] == "robust"), None)
        # The demo's program: specialised, with every lever (the most '+' parts).
        demo = max(glsl, key=lambda r: (r["specialized"] == "1", len(r["lever"].split("+")) if r["lever"] else 0))
        fast = min(glsl, key=lambda r: ms(r["frame_ms"]))
        out.append((f"{fast['width']}x{fast['height']}", scene,
                    f"{ms(base['frame_ms']):.1f}" if base else "n/a",
                    f"{ms(demo['frame_ms']):.1f} ({setting_name(demo)})", x_embree(mine, demo),
                    f"{ms(fast['frame_ms']):.1f} ({setting_name(fast)})", x_embree(mine, fast)))
    return out


def fur_rows(rows, size):
    out = []
    keys = sorted({(r["mesh"], int(r["triangles"])) for r in rows}, key=lambda k: (k[0], k[1]))
    for mesh, triangles in keys:
        mine = [r for r in rows if r["mesh"] == mesh and int(r["triangles"]) == triangles]
        shells = {int(r["shells"]): ms(r["frame_ms"]) for r in mine
                  if r["technique"] == "shells_and_fins" and r["fins"] == "1"}
        shader = next((ms(r["frame_ms"]) for r in mine if r["technique"] == "fur_shader"), None)
        listed = ", ".join(f"{n}: {v:.1f}" for n, v in sorted(shells.items()) if v is not None) or "n/a"
        sixteen = shells.get(16) or (shells[max(shells)] if shells else None)
        ratio = f"{sixteen / shader:.2f}" if sixteen and shader else "n/a"
        out.append((size, f"{mesh}, {triangles}", listed, f"{shader:.1f}" if shader else "n/a", ratio))
    return out


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "| " + " | ".join("---" for _ in header) + " |"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: summarise.py OUT REFERENCES")
    out, references = sys.argv[1], sys.argv[2]
    print(f"# RayLab measured on {gl_string(out)}\n")
    print(f"{time.strftime('%Y-%m-%d %H:%M')}, host {platform.node()}, {os.cpu_count()} CPU threads; "
          f"written by `tools/gpu/measure.sh` ({out}).\n")
    print(f"## Every check view against {references}\n")
    print(table(["stage", "result", "views passed", "function checks passed", "worst view (pixels differing)",
                 "failed"], check_rows(out)))
    # Each track: its CSV's name and the function that makes its table rows.
    tracks = {"bench-raytrace": ("bench.csv", raytrace_rows), "bench-fur": ("fur.csv", fur_rows)}
    rows = {track: [] for track in tracks}
    missing = []
    # Every bench that ran left a log; its folder may be missing (it failed early).
    for log in sorted(os.listdir(out)):
        if not (log.startswith("bench-") and log.endswith(".log")):
            continue
        name = log[:-4]
        size = name.rsplit("-", 1)[-1]
        if size == "quick":  # `raylab bench --quick`: the small grid at 160x120
            size = "160x120 (quick)"
        track = next((t for t in tracks if name.startswith(t)), None)
        if track is None:
            continue
        csv_name, make_rows = tracks[track]
        path = os.path.join(out, name, csv_name)
        if os.path.exists(path):
            rows[track] += make_rows(read_csv(path), size)
        else:
            missing.append(name)
    ray, fur = rows["bench-raytrace"], rows["bench-fur"]
    print("\n## Ray tracer: `raylab bench`, depth 8, shadows on\n")
    print(table(["size", "scene", "baseline (ms)", "the demo's program (ms)", "its x Embree",
                 "fastest setting (ms)", "its x Embree"], ray))
    print("\nx Embree: the frame time over Embree casting the same rays on the machine's CPU "
          "cores, in the same run.")
    print("\n## Fur: `raylab bench --track fur`\n")
    print(table(["size", "mesh, triangles", "shells and fins, by shell count (ms)", "fur shader (ms)",
                 "16 shells + fins / fur shader"], fur))
    if missing:
        print("\n## Benches that left no table\n")
        rows = []
        for name in missing:
            with open(os.path.join(out, name + ".log"), encoding="utf-8", errors="replace") as f:
                last = (f.read().strip().splitlines() or ["no output"])[-1]
            rows.append((name, "FAIL", last))
        print(table(["bench", "result", "its log's last line"], rows))


if __name__ == "__main__":
    main()
