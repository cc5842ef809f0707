"""The bar chart of the side-by-side speed benchmarks: per label the median
run's wall, assembly and solve times, whiskers over all its runs."""
import csv


def timing_columns(summary):
    """The columns of a speed benchmark's row from a scene's summary:
    DoFs, wall, assembly, solve and error-estimate seconds, Newton and
    Krylov iterations, and the depths."""
    solver, timings = summary["solver"], summary["timings"]
    return dict(
        dofs=summary["dofs"], wall_s=round(timings["total"], 1),
        assembly_s=round(timings.get("assembly", 0.), 1),
        solve_s=round(timings.get("solve", 0.), 1),
        estimate_s=round(timings.get("error estimate", 0.), 1),
        newton_iterations=solver["newton_iterations"],
        krylov_iterations=solver["linear_iterations"],
        depths_mm=" ".join(f"{d:.6f}" for d in summary["depth_mm"]))


def plot_timings(path, label_key, title, png=None):
    """Reads the CSV at path (columns label_key, wall_s, assembly_s,
    solve_s, newton_iterations) and writes png (default: path with .png)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(path) as f:
        rows = list(csv.DictReader(f))
    labels = list(dict.fromkeys(r[label_key] for r in rows))
    fig, ax = plt.subplots(figsize=(2.2 * len(labels) + 2, 4))
    for k, label in enumerate(labels):
        runs = sorted((r for r in rows if r[label_key] == label),
                      key=lambda r: float(r["wall_s"]))
        median = runs[len(runs) // 2]
        for offset, key, colour in ((-0.25, "wall_s", "0.6"),
                                    (0., "assembly_s", "tab:blue"),
                                    (0.25, "solve_s", "tab:orange")):
            values = [float(r[key]) for r in runs]
            ax.bar(k + offset, float(median[key]), width=0.25, color=colour,
                   label=key.split("_")[0] if k == 0 else None)
            ax.plot([k + offset] * 2, [min(values), max(values)], color="k",
                    lw=1)
        ax.text(k - 0.25, max(float(r["wall_s"]) for r in runs) * 1.02,
                f"{median['newton_iterations']} Newton", ha="center",
                fontsize=8)
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels([label.replace(", ", "\n", 1) for label in labels],
                       fontsize=8)
    ax.set_ylabel("time (s)")
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    png = png or path.replace(".csv", ".png")
    fig.savefig(png, dpi=120)
    print("wrote", png)
