"""Tables and plots of docs/paper-reproduction.md from the stats JSON of docs/reproduce-paper.sh."""
import json
import subprocess
import sys

name, data, images = sys.argv[1], sys.argv[2], sys.argv[3]
runs = {n: json.load(open(f"{data}/paper-{name}-mesh-{n}.json")) for n in (64, 128, 256)}

print(f"Table 1.1 / 1.2 ({name}, hierarchical mapping, 4096 PEs, to C = 0.95)")
print("| resolution | iterations | emulated MP-1 s/iteration | avg max depth (a) | avg max depth (b) |")
print("|---|---|---|---|---|")
for n, run in runs.items():
    its = run["per_iteration"]
    mean = lambda key: sum(i[key] for i in its) / len(its)
    print(f"| {n}x{n} | {len(its)} | {mean('emulated_seconds'):.3f} | {mean('depth_a_max'):.1f} | {mean('depth_b_max'):.1f} |")

reuse = json.load(open(f"{data}/paper-{name}-reuse.json"))["per_iteration"]
print("\nTable 1.3: form-factor rows reused (shooters shot before), cumulative")
print("| iteration | rows reused so far | convergence % |")
print("|---|---|---|")
marks = [13, 32, 59, 101, 177, 392, 1105, 2462]
for it in reuse:
    if it["iteration"] in marks or it is reuse[-1]:
        print(f"| {it['iteration']} | {it['reused_rows_total']} | {100 * it['convergence']:.2f} |")


def plot(png, title, xlabel, ylabel, series, logy=False):
    script = [f"set terminal pngcairo size 1000,600 noenhanced", f"set output '{png}'", f"set title '{title}'",
              f"set xlabel '{xlabel}'", f"set ylabel '{ylabel}'", "set grid", "set key bottom right"]
    if logy:
        script.append("set logscale y")
    script.append("plot " + ", ".join(f"'-' with {style} title '{t}'" for t, _, style in series))
    for _, points, _ in series:
        script += [f"{x} {y}" for x, y in points] + ["e"]
    subprocess.run(["gnuplot"], input="\n".join(script), text=True, check=True)


plot(f"{images}/paper-{name}-convergence.png", f"Figure 1.3: convergence by single-plane resolution ({name}, mesh backend)",
     "iteration", "convergence C %",
     [(f"{n}x{n}", [(i["iteration"], 100 * i["convergence"]) for i in run["per_iteration"]], "lines")
      for n, run in runs.items()])
for stage in ("a", "b"):
    plot(f"{images}/paper-{name}-depth-{stage}.png",
         f"Figure 1.4: max item-buffer depth at stage ({stage}) per iteration ({name})", "iteration",
         "max depth over PEs",
         [(f"{n}x{n}", [(i["iteration"], i[f"depth_{stage}_max"]) for i in run["per_iteration"]], "linespoints")
          for n, run in runs.items()])
print(f"\nwrote {images}/paper-{name}-convergence.png, -depth-a.png, -depth-b.png")
