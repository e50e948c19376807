"""Tables and plots of docs/paper-reproduction.md from the stats JSON of docs/reproduce-paper.sh."""
import json
import subprocess
import sys

name, data, images = sys.argv[1], sys.argv[2], sys.argv[3]
mappings = ("hierarchical", "cut-and-stack", "adaptive")
resolutions = (64, 128, 256)
stats = {(m, n): json.load(open(f"{data}/paper-{name}-{m}-{n}.json")) for m in mappings for n in resolutions}
runs = {n: stats[("hierarchical", n)] for n in resolutions}


def to95(run):
    """The iterations up to and including the first at C >= 0.95 (where the tables stop)."""
    its = run["per_iteration"]
    end = next((k for k, i in enumerate(its) if i["convergence"] >= 0.95), len(its) - 1)
    return its[:end + 1]


def mean(run, key):
    its = to95(run)
    return sum(i[key] for i in its) / len(its)


print(f"Table 1.1 / 1.2 ({name}, 4096 PEs, to C = 0.95), every mapping; s/iteration are averages")
print("| mapping | resolution | iterations | emulated MP-1 s/iteration | host s/iteration | avg max depth (a) | avg max depth (b) |")
print("|---|---|---|---|---|---|---|")
for (m, n), run in stats.items():
    print(f"| {m} | {n}x{n} | {len(to95(run))} | {mean(run, 'emulated_seconds'):.3f} | "
          f"{mean(run, 'seconds'):.4f} | {mean(run, 'depth_a_max'):.1f} | {mean(run, 'depth_b_max'):.1f} |")

reuse = json.load(open(f"{data}/paper-{name}-reuse.json"))["per_iteration"]
print("\nTable 1.3: form-factor rows reused (shooters shot before), cumulative")
print("| iteration | rows reused so far | convergence % |")
print("|---|---|---|")
marks = [13, 32, 59, 101, 177, 392, 1105, 2462]
for it in reuse:
    if it["iteration"] in marks or it is reuse[-1]:
        print(f"| {it['iteration']} | {it['reused_rows_total']} | {100 * it['convergence']:.2f} |")


def plot(png, title, xlabel, ylabel, series, settings=()):
    script = [f"set terminal pngcairo size 1000,600 noenhanced", f"set output '{png}'", f"set title '{title}'",
              f"set xlabel '{xlabel}'", f"set ylabel '{ylabel}'", "set grid", "set key bottom right", *settings]
    script.append("plot " + ", ".join(f"'-' with {style} title '{t}'" for t, _, style in series))
    for _, points, _ in series:
        script += [f"{x} {y}" for x, y in points] + ["e"]
    subprocess.run(["gnuplot"], input="\n".join(script), text=True, check=True)


plot(f"{images}/paper-{name}-convergence.png", f"Figure 1.3: convergence by single-plane resolution ({name}, mesh backend)",
     "iteration", "convergence C %",
     [(f"{n}x{n}", [(i["iteration"], 100 * i["convergence"]) for i in run["per_iteration"]], "lines")
      for n, run in runs.items()])
style = "linespoints" if max(len(r["per_iteration"]) for r in runs.values()) <= 100 else "lines"
for stage in ("a", "b"):
    plot(f"{images}/paper-{name}-depth-{stage}.png",
         f"Figure 1.4: max item-buffer depth at stage ({stage}) per iteration ({name})", "iteration",
         "max depth over PEs",
         [(f"{n}x{n}", [(i["iteration"], i[f"depth_{stage}_max"]) for i in run["per_iteration"]], style)
          for n, run in runs.items()])

# The paper's Tables 1.1-1.3 (its section 1.6) beside this scene's, drawn.
paper_seconds = {64: 0.24, 128: 0.45, 256: 2.15}
paper_depth = {"a": {64: 10.6, 128: 6.5, 256: 4.4}, "b": {64: 20.4, 128: 11.3, 256: 10.6}}
paper_reuse = [(53.03, 2), (76.57, 3), (88.76, 3), (94.40, 3), (97.20, 6), (98.61, 39), (99.30, 216)]
resolution_axis = ["set key outside right", "set logscale x 2", "set xtics (64, 128, 256)", "set xrange [45:360]", "set logscale y"]
plot(f"{images}/paper-{name}-table11.png", f"Table 1.1: MP-1 seconds per iteration to C = 0.95 ({name})",
     "single-plane resolution", "MP-1 seconds per iteration (log)",
     [("paper (Sitterson 365 office, measured)", paper_seconds.items(), "linespoints")]
     + [(f"radmesh {m} (emulated)", [(n, mean(stats[(m, n)], "emulated_seconds")) for n in resolutions], "linespoints")
        for m in mappings], resolution_axis)
plot(f"{images}/paper-{name}-table12.png", f"Table 1.2: average max item-buffer depth to C = 0.95 ({name})",
     "single-plane resolution", "average of the max depth over PEs (log)",
     [(f"paper ({stage})", paper_depth[stage].items(), "linespoints") for stage in ("a", "b")]
     + [(f"radmesh {m} ({stage})", [(n, mean(stats[(m, n)], f"depth_{stage}_max")) for n in resolutions], "linespoints")
        for m in mappings for stage in ("a", "b")], resolution_axis)
plot(f"{images}/paper-{name}-table13.png", f"Table 1.3: form-factor rows reused against convergence ({name})",
     "convergence C %", "rows reused so far", [("paper", paper_reuse, "linespoints"),
     ("radmesh (native, 128x128)", [(100 * i["convergence"], i["reused_rows_total"]) for i in reuse], "lines")],
     ["set xrange [50:100]", "set key top left"])
print(f"\nwrote {images}/paper-{name}-convergence.png, -depth-a.png, -depth-b.png, -table11.png, -table12.png, -table13.png")
