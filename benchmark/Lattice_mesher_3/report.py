#!/usr/bin/python3
# Copyright (c) 2026 Lattice_mesher_3 developers.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Reporting of benchmark/run: reads the lattice-benchmark outputs of RUNS (<model>/<method>.json and
# .csv, scaling/bcc_<n>_t<threads>.json) and writes to OUT the per-model tables (results_<model>.md
# and .csv), their histograms (hist_<model>.png), scaling.png and the summary results.md.
# A method with no run in RUNS (neither .json nor .log) keeps its row of the earlier
# OUT/results_<model>.csv, with the date and load average of its own run, and is marked as kept;
# so does the scaling section of the earlier results.md when RUNS has no scaling runs.
#   report.py RUNS OUT --models a,b [--threads T] [--scaling-model M] [--quick]

import argparse
import csv
import datetime
import glob
import json
import os
import platform
import re
import subprocess

import matplotlib

matplotlib.use("Agg")   # no display needed
import matplotlib.pyplot as plt
import numpy as np

METHODS = [
    ("bcc", "ours BCC"),
    ("fcc", "ours FCC"),
    ("gaussian", "Particle2013 (Gaussian kernel)"),
    ("cvt", "CVT (Mesh_3 Lloyd)"),
    ("odt", "ODT (Mesh_3)"),
    ("cvt-pe", "CVT + perturb + exude"),
    ("odt-pe", "ODT + perturb + exude"),
    ("tetgen", "TetGen -pq"),
    ("gmsh", "Gmsh HXT + optimizer"),
]
LABEL = dict(METHODS)
TOLERANCE = 0.05   # of the vertex-count tuning in lattice-benchmark

# (column, JSON path, decimals); the paper's columns, then time and memory
COLUMNS = [
    ("#V", ("vertices",), 0),
    ("θmin min", ("theta_min", "min"), 2), ("θmin mean", ("theta_min", "mean"), 2), ("θmin σ", ("theta_min", "std"), 2),
    ("θmax max", ("theta_max", "max"), 2), ("θmax mean", ("theta_max", "mean"), 2), ("θmax σ", ("theta_max", "std"), 2),
    ("ρ min", ("rho", "min"), 4), ("ρ mean", ("rho", "mean"), 4), ("ρ σ", ("rho", "std"), 4),
    ("κ min", ("kappa", "min"), 4), ("κ mean", ("kappa", "mean"), 4), ("κ σ", ("kappa", "std"), 4),
    ("ε mean", ("epsilon", "mean"), 2), ("ε σ", ("epsilon", "std"), 2),
    ("#T<20°", ("below20",), 0), ("#T<40°", ("below40",), 0), ("#T", ("tets",), 0),
    ("time (s)", ("seconds", "total"), 2), ("peak RSS (MB)", ("peak_rss_mb",), 1),
]
HISTOGRAMS = [("dihedral", "dihedral angle (°)", (0, 180)), ("rho", "ρ", (0, 1)),
              ("kappa", "κ", (0, 1)), ("epsilon", "ε (°), against the method's lattice one-ring", (0, 45))]

NOTES = """- Every method meshes the same validated surface (closed, not self-intersecting) to about the
  target vertex count: its size parameter (ours: the requested count; Mesh_3: one size for cells,
  facets and feature edges, facet distance size/10, facet angle 25°, radius-edge ratio 3; TetGen:
  the maximum volume of `-pqa`; Gmsh: one mesh size, `Mesh.MeshSizeMin` = `Mesh.MeshSizeMax`) is
  tuned by secant steps on log #V until #V is within ±5 % of the target (at most 6 attempts; †
  marks a count outside). Each attempt runs in its own process.
- time: wall time of the final meshing call only (no tuning, domain set-up or measurement); peak
  RSS: of the process that ran it. Mesh_3, TetGen and Gmsh run sequentially (CGAL's parallel
  Mesh_3 needs TBB, Gmsh is given `-nt 1`); ours ran with {threads} thread(s).
- CVT and ODT: `make_mesh_3` with `lloyd()` / `odt()` at CGAL's defaults on a
  `Polyhedral_mesh_domain_with_features_3` with the same 60° features as ours; raw rows without
  the sliver perturber and exuder (the paper's rows), "+ perturb + exude" rows with CGAL's
  defaults, as a CGAL user runs it. Particle2013: the hole-less Gaussian kernel as published, from
  a random start at the final count, no insertion or deletion, then our flips and smoothing.
- Gmsh (Debian's `gmsh` {gmsh_version} program, as its user meshes a triangulated surface): the
  surface merged as a Gmsh mesh (coordinates at full precision), `ClassifySurfaces{{60°, 1, 1, π}}`
  and `CreateGeometry` (the same 60° features as ours, patches split until parametrizable), one
  `Surface Loop` and `Volume`, then `gmsh -3 -nt 1` with `Mesh.Algorithm3D = 10` (HXT),
  `Mesh.Optimize = 1`, `Mesh.MeshSizeMin` = `Mesh.MeshSizeMax` = the tuned size and
  `Mesh.MeshSizeFromCurvature = 0`, output as Medit and read back. Gmsh remeshes curves and
  surfaces at the size (Frontal-Delaunay) before HXT fills the volume. With HXT, `Mesh.Optimize`
  is HXT's own optimizer (smoothing, edge removal and growing sphere cavities on tetrahedra of
  quality below `Mesh.OptimizeThreshold` = 0.3); Gmsh 4.8 runs none of its other optimizers after
  HXT (`Mesh.OptimizeNetgen` is ignored there, and Debian's Gmsh has no Netgen), and an explicit
  `OptimizeMesh` after it changed little (fandisk: 16,900 → 16,810 tetrahedra below 40°). Where
  Gmsh cannot parametrize a classified patch at its defaults ("Wrong topology of boundary mesh for
  parametrization", after which HXT fails: couplingdown), the run is repeated with smaller patches,
  `Mesh.ReparamMaxTriangles = 500` (3000, 2000 and 1000 fail too), and only that run is timed. Its
  time is the sum of the wall times Gmsh reports for meshing 1D, 2D and 3D (surface remeshing,
  HXT and its optimizer; reading and classifying the surface and writing the mesh, the analogue
  of the others' domain set-up and output, are left out: see the stages below); its peak RSS is
  that of the gmsh process.
- Every mesh is measured by `compute_mesh_quality()` with the identity field; ε is measured
  against the FCC one-ring for ours with FCC and against the BCC one-ring for every other method.
  ‡ marks a mesh that fails `check_tetrahedral_mesh()` (see its log)."""


def get(record, path):
    for key in path:
        record = record[key]
    return record


def load_json(path):
    with open(path) as f:
        return json.load(f)


def run_provenance(runs, path):
    """The date of a run (its file's) and the load average before the runs in RUNS."""
    date = datetime.date.fromtimestamp(os.path.getmtime(path)).isoformat()
    load = "unknown"
    if os.path.exists(os.path.join(runs, "loadavg")):
        with open(os.path.join(runs, "loadavg")) as f:
            load = ", ".join(f.read().split()[:3])
    return date, load


def earlier_report(out):
    """The date and load average that the earlier OUT/results.md states, for rows kept from
    tables written before their date and load were in the CSV files."""
    date, load = "unknown", "unknown"
    path = os.path.join(out, "results.md")
    if os.path.exists(path):
        with open(path) as f:
            text = f.read()
        found = re.search(r"^Generated by .* on (\d{4}-\d{2}-\d{2})\.", text, re.MULTILINE)
        date = found.group(1) if found else date
        found = re.search(r"load average before the runs \(1, 5, 15 min\): ([^\n;]*)", text)
        load = found.group(1).strip() if found else load
    return date, load


def earlier_rows(out, model, earlier):
    """The rows of the earlier OUT/results_<model>.csv by method, as records (None for a failed
    run), marked as kept."""
    path = os.path.join(out, f"results_{model}.csv")
    rows = {}
    if not os.path.exists(path):
        return rows
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row[COLUMNS[0][0]] == "failed":
                rows[row["method"]] = None
                continue
            record = {}
            for name, path_, decimals in COLUMNS:
                parent = record
                for key in path_[:-1]:
                    parent = parent.setdefault(key, {})
                parent[path_[-1]] = float(row[name]) if decimals else int(float(row[name]))
            target = float(row["target_vertices"])
            record["target_vertices"] = int(target) if target.is_integer() else target
            record["valid"] = row["valid"] == "True"
            record["date"] = row.get("date") or earlier[0]
            record["loadavg"] = row.get("loadavg") or earlier[1]
            record["kept"] = True
            rows[row["method"]] = record
    return rows


def model_runs(runs, model, kept=None):
    """The (method, record or None) pairs of a model, in table order; None for a failed run. A
    method with no run in RUNS takes its record from `kept` (earlier_rows()) when it has one."""
    result = []
    for method, _ in METHODS:
        path = os.path.join(runs, model, method + ".json")
        if os.path.exists(path):
            record = load_json(path)
            record["date"], record["loadavg"] = run_provenance(runs, path)
            result.append((method, record))
        elif os.path.exists(os.path.join(runs, model, method + ".log")):
            result.append((method, None))
        elif kept and method in kept:
            result.append((method, kept[method]))
    return result


def method_label(method, record):
    label = LABEL[method]
    return label + " ‡" if record is not None and not record.get("valid", True) else label


def cell(record, column):
    name, path, decimals = column
    value = get(record, path)
    text = f"{value:.{decimals}f}" if decimals else str(int(value))
    if name == "#V" and abs(value / record["target_vertices"] - 1) > TOLERANCE:
        text += " †"
    return text


def write_model_tables(runs, out, model, rows):
    target = next((r["target_vertices"] for _, r in rows if r is not None), None)
    header = ["method"] + [c[0] for c in COLUMNS]
    lines = [f"### {model} (target {target:.0f} vertices)" if target else f"### {model}", "",
             "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    with open(os.path.join(out, f"results_{model}.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["method"] + [c[0] for c in COLUMNS] + ["target_vertices", "valid", "date", "loadavg"])
        for method, record in rows:
            if record is None:
                lines.append(f"| {LABEL[method]} | failed (see runs/{model}/{method}.log) |" + " |" * (len(COLUMNS) - 1))
                writer.writerow([method] + ["failed"] + [""] * (len(COLUMNS) + 3))
                continue
            lines.append("| " + " | ".join([method_label(method, record)] + [cell(record, c) for c in COLUMNS]) + " |")
            writer.writerow([method] + [get(record, c[1]) for c in COLUMNS]
                            + [record["target_vertices"], record.get("valid", True), record["date"], record["loadavg"]])
    kept = {}
    for method, record in rows:
        if record is not None and record.get("kept"):
            kept.setdefault((record["date"], record["loadavg"]), []).append(LABEL[method])
    for (date, load), labels in sorted(kept.items()):
        lines += ["", f"Kept from the earlier tables (runs of {date}, load average before them {load}; "
                      f"not rerun here): {', '.join(labels)}."]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, f"results_{model}.md"), "w") as f:
        f.write(text)
    return text


def read_histograms(path):
    data = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            data.setdefault(row["quantity"], ([], []))
            data[row["quantity"]][0].append(float(row["value"]))
            data[row["quantity"]][1].append(int(row["count"]))
    return data


def plot_histograms(runs, out, model, rows):
    """Writes the histograms of the rows that have them in RUNS: hist_<model>.png, or when some
    rows are kept from earlier tables (whose histograms are in the earlier hist_<model>.png),
    hist_<model>_<methods>.png. Returns the file name, or None when no row has histograms."""
    plotted = [m for m, r in rows if r is not None and not r.get("kept")
               and os.path.exists(os.path.join(runs, model, m + ".csv"))]
    if not plotted:
        return None
    name = f"hist_{model}.png"
    if any(r is not None and r.get("kept") for _, r in rows):
        name = f"hist_{model}_{'_'.join(plotted)}.png"
    figure, axes = plt.subplots(2, 2, figsize=(12, 8))
    colors = plt.get_cmap("tab10")
    for k, (method, record) in enumerate(rows):
        path = os.path.join(runs, model, method + ".csv")
        if method not in plotted:
            continue
        data = read_histograms(path)
        for ax, (quantity, _, _) in zip(axes.flat, HISTOGRAMS):
            values, counts = data[quantity]
            total = max(sum(counts), 1)
            ax.step(values, [c / total for c in counts], where="mid", color=colors(k), linewidth=1,
                    label=f"{LABEL[method]} ({record['vertices']} V)")
    for ax, (_, title, limits) in zip(axes.flat, HISTOGRAMS):
        ax.set_xlim(*limits)
        ax.set_xlabel(title)
        ax.set_ylabel("fraction")
    axes.flat[0].legend(fontsize=7)
    figure.suptitle(f"{model}: distributions per method (isotropic space, T = I)")
    figure.tight_layout()
    figure.savefig(os.path.join(out, name), dpi=110)
    plt.close(figure)
    return name


def speed_ratios(rows_of, models):
    pairs = [(a, b) for a in ("bcc", "fcc") for b in ("cvt", "odt", "cvt-pe", "odt-pe", "gmsh")]
    header = ["model"] + [f"{a.upper()} / {LABEL[b].split(' (')[0]}" for a, b in pairs]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for model in models:
        times = {m: r["seconds"]["total"] for m, r in rows_of[model] if r is not None}
        cells = [f"{times[a] / times[b]:.2f}" if a in times and b in times and times[b] > 0 else "–"
                 for a, b in pairs]
        lines.append("| " + " | ".join([model] + cells) + " |")
    return "\n".join(lines) + "\n"


def our_stages(rows_of, models):
    """Where ours spends the time of its runs (lattice-benchmark's stages, as
    Lattice_mesher_3::Stage_times_visitor adds them up), or "" when no run has them."""
    columns = [("insertion", lambda s: s.get("insertion", 0.)),
               ("L-BFGS, finest level", lambda s: s.get("optimization, level 0", 0.)),
               ("L-BFGS, coarser levels", lambda s: sum(v for k, v in s.items()
                                                         if k.startswith("optimization, level ") and k != "optimization, level 0")),
               ("deletion", lambda s: s.get("deletion", 0.)),
               ("tetrahedralization", lambda s: s.get("tetrahedralization", 0.)),
               ("flips", lambda s: s.get("flips", 0.)),
               ("smoothing", lambda s: s.get("smoothing", 0.)),
               ("contractions, peeling, labels", lambda s: sum(s.get(k, 0.) for k in ("contractions", "peeling", "labels")))]
    header = ["model", "method"] + [c for c, _ in columns] + ["sizing and set-up", "time"]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for model in models:
        for method in ("bcc", "fcc"):
            record = dict(rows_of[model]).get(method)
            if record is None or "stages" not in record["seconds"]:
                continue
            s, total = record["seconds"]["stages"], record["seconds"]["total"]
            cells = [f"{f(s):.2f}" for _, f in columns] + [f"{total - sum(s.values()):.2f}", f"{total:.2f}"]
            lines.append("| " + " | ".join([model, method.upper()] + cells) + " |")
    return "\n".join(lines) + "\n" if len(lines) > 2 else ""


def gmsh_stages(rows_of, models):
    """Gmsh's own wall times of its stages in the reported runs (lattice-benchmark's
    gmsh_wall_seconds), or "" when there are none."""
    lines = ["| model | 1D | 2D | 3D (HXT + optimizer) | time (1D + 2D + 3D) | the whole gmsh process |",
             "|---|---|---|---|---|---|"]
    for model in models:
        record = dict(rows_of[model]).get("gmsh")
        if record is None or "gmsh_wall_seconds" not in record:
            continue
        w = record["gmsh_wall_seconds"]
        patches = record.get("gmsh_reparam_max_triangles")
        lines.append(f"| {model}{f' (patches of ≤ {patches} triangles)' if patches else ''} | {w['mesh_1d']:.2f} | "
                     f"{w['mesh_2d']:.2f} | {w['mesh_3d']:.2f} | {record['seconds']['total']:.2f} | {w['process']:.2f} |")
    return "\n".join(lines) + "\n" if len(lines) > 2 else ""


def fit_exponent(x, y):
    """Least-squares slope of log y against log x."""
    return float(np.polyfit(np.log(x), np.log(y), 1)[0])


def scaling(runs, out, model):
    records = {}
    for path in glob.glob(os.path.join(runs, "scaling", "bcc_*_t*.json")):
        n, t = map(int, re.match(r"bcc_(\d+)_t(\d+)\.json", os.path.basename(path)).groups())
        records[(n, t)] = load_json(path)
    if not records:
        return ""
    lines = [f"BCC on {model}, one run per count without tuning.", "",
             "| requested | threads | #V | #T | time (s) | peak RSS (MB) | speed-up 1→2 threads |",
             "|---|---|---|---|---|---|---|"]
    for n, t in sorted(records):
        r = records[(n, t)]
        speedup = "–"
        if t == 2 and (n, 1) in records:
            speedup = f"{records[(n, 1)]['seconds']['total'] / r['seconds']['total']:.2f}"
        lines.append(f"| {n} | {t} | {r['vertices']} | {r['tets']} | {r['seconds']['total']:.2f} | "
                     f"{r['peak_rss_mb']:.1f} | {speedup} |")
    lines.append("")
    figure, (ax_time, ax_memory) = plt.subplots(1, 2, figsize=(11, 4.5))
    for t in sorted({t for _, t in records}):
        series = [records[k] for k in sorted(records) if k[1] == t]
        v = [r["vertices"] for r in series]
        seconds = [r["seconds"]["total"] for r in series]
        memory = [r["peak_rss_mb"] for r in series]
        if len(series) < 2:
            continue
        a_time, a_memory = fit_exponent(v, seconds), fit_exponent(v, memory)
        lines.append(f"- {t} thread(s): time ∝ #V^{a_time:.2f}, peak RSS ∝ #V^{a_memory:.2f} (least squares on log-log)")
        ax_time.loglog(v, seconds, "o-", label=f"{t} thread(s), exponent {a_time:.2f}")
        ax_memory.loglog(v, memory, "o-", label=f"{t} thread(s), exponent {a_memory:.2f}")
    for ax, title in ((ax_time, "time (s)"), (ax_memory, "peak RSS (MB)")):
        ax.set_xlabel("#V")
        ax.set_ylabel(title)
        ax.legend(fontsize=8)
        ax.grid(True, which="both", alpha=.3)
    figure.suptitle(f"BCC on {model}: scaling")
    figure.tight_layout()
    figure.savefig(os.path.join(out, "scaling.png"), dpi=110)
    plt.close(figure)
    return "\n".join(lines) + "\n\n![scaling](scaling.png)\n"


def command_output(command):
    try:
        return subprocess.run(command, capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def earlier_scaling(out, earlier_date):
    """The scaling section of the earlier OUT/results.md, marked as kept, or "" without one."""
    path = os.path.join(out, "results.md")
    if not os.path.exists(path):
        return ""
    with open(path) as f:
        found = re.search(r"^## Scaling\n\n(.*?)(?=^## |\Z)", f.read(), re.MULTILINE | re.DOTALL)
    if not found:
        return ""
    text = found.group(1).rstrip("\n") + "\n"
    if not text.startswith("Kept from"):
        text = f"Kept from the earlier report (runs of {earlier_date}; no scaling runs here).\n\n" + text
    return text


def gmsh_version():
    version = command_output(["dpkg-query", "-W", "-f=${Version}", "gmsh"])
    return version.split("+")[0]


def machine(runs):
    with open("/proc/cpuinfo") as f:
        models = re.findall(r"^model name\s*:\s*(.*)$", f.read(), re.MULTILINE)
    with open("/proc/meminfo") as f:
        memory_kb = int(re.search(r"^MemTotal:\s*(\d+)", f.read(), re.MULTILINE).group(1))
    os_name = "unknown"
    if os.path.exists("/etc/os-release"):
        with open("/etc/os-release") as f:
            found = re.search(r'^PRETTY_NAME="?([^"\n]*)', f.read(), re.MULTILINE)
            os_name = found.group(1) if found else os_name
    version = lambda p: command_output(["dpkg-query", "-W", "-f=${Version}", p])
    load = "unknown"
    if os.path.exists(os.path.join(runs, "loadavg")):
        with open(os.path.join(runs, "loadavg")) as f:
            load = ", ".join(f.read().split()[:3])
    return "\n".join([
        f"- CPU: {models[0] if models else platform.processor()} ({len(models)} logical CPUs in /proc/cpuinfo, "
        f"nproc = {command_output(['nproc'])}), {memory_kb / 2**20:.1f} GiB memory; load average before "
        f"the runs (1, 5, 15 min): {load}",
        f"- {os_name}, kernel {platform.release()}; {command_output(['g++', '--version']).splitlines()[0]}",
        f"- CGAL {version('libcgal-dev')}, TetGen {version('libtet1.5-dev')}, Gmsh {version('gmsh')}, "
        f"Eigen {version('libeigen3-dev')}, LBFGS++ {version('liblbfgspp-dev')}; Release build (-O3 -frounding-math)",
    ])


def main():
    parser = argparse.ArgumentParser(description="Tables and figures of benchmark/run.")
    parser.add_argument("runs")
    parser.add_argument("out")
    parser.add_argument("--models", required=True)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--scaling-model", default="fandisk")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    models = [m for m in args.models.split(",") if m]
    os.makedirs(args.out, exist_ok=True)
    earlier = earlier_report(args.out)   # read before results.md is rewritten
    rows_of = {model: model_runs(args.runs, model, earlier_rows(args.out, model, earlier)) for model in models}

    parts = ["# Baselines benchmark", "",
             f"Generated by `benchmark/run{' --quick' if args.quick else ''}` on "
             f"{datetime.date.today().isoformat()}."]
    if args.quick:
        parts.append("**Quick run: every vertex count ×0.1, a test of the pipeline, not results.**")
    parts += ["", "## Machine", "", machine(args.runs), "", "## How the methods were run", "",
              NOTES.format(threads=args.threads, gmsh_version=gmsh_version()), "",
              "## Quality, time and memory per model", ""]
    for model in models:
        rows = rows_of[model]
        if not rows:
            parts += [f"### {model}", "", "no runs", ""]
            continue
        parts.append(write_model_tables(args.runs, args.out, model, rows))
        figure = plot_histograms(args.runs, args.out, model, rows)
        earlier_figure = f"hist_{model}.png"
        if any(r is not None and r.get("kept") for _, r in rows) and os.path.exists(os.path.join(args.out, earlier_figure)):
            parts += [f"![{model}, the kept rows]({earlier_figure})", ""]
        if figure:
            parts += [f"![{model}]({figure})", ""]
    parts += ["## Speed ratios", "",
              "Time of ours divided by the time of a baseline on the same model, from the rows above "
              "(below 1: ours is faster).", "", speed_ratios(rows_of, models)]
    ours = our_stages(rows_of, models)
    if ours:
        parts += ["## Where ours spends its time", "",
                  "Seconds of each stage of the runs above (the sums over the rounds and repeats); the rest of the "
                  "meshing call is the sizing and the set-up of the mesher.", "", ours]
    stages = gmsh_stages(rows_of, models)
    if stages:
        parts += ["## Gmsh's stages", "",
                  "Wall times in seconds that Gmsh reports for each stage of the runs above; the table's time is "
                  "1D + 2D + 3D, the whole process also reads and classifies the surface, creates the geometry "
                  "and writes the mesh.", "", stages]
    scaling_text = scaling(args.runs, args.out, args.scaling_model) or earlier_scaling(args.out, earlier[0])
    if scaling_text:
        parts += ["## Scaling", "", scaling_text]
    with open(os.path.join(args.out, "results.md"), "w") as f:
        f.write("\n".join(parts))


if __name__ == "__main__":
    main()
