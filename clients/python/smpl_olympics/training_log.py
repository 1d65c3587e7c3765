"""What a training run writes: metrics.csv (one row per iteration) and curves.png, and the
progress line on the terminal."""
import csv
import os
import sys


def read_metrics(run_dir):
    """A run's metrics.csv as a list of dicts (strings, "" where a figure had no value)."""
    with open(os.path.join(run_dir, "metrics.csv")) as f:
        return list(csv.DictReader(f))


class TrainingLog:
    def __init__(self, run_dir, term_names, resume=False, until_iteration=None):
        """`resume`: keep the rows already there up to `until_iteration` (the checkpoint's: a
        run killed after it logged later iterations redoes them)."""
        self.path = os.path.join(run_dir, "metrics.csv")
        self.fields = (["iteration", "samples", "wall_s", "samples_per_s", "episodes",
                        "episode_return", "episode_length", "score", "win_rate", "touch_rate"] +
                       [f"term_{n}" for n in term_names] +
                       ["policy_loss", "value_loss", "approx_kl", "update_steps", "std", "outcomes_missed"])
        rows = read_metrics(run_dir) if resume and os.path.exists(self.path) else []
        kept = [r for r in rows if until_iteration is None or int(r["iteration"]) <= until_iteration]
        if not rows or list(rows[0]) != self.fields or len(kept) != len(rows):
            rows = kept
            # A new run, or one stored by a version that logged other figures: its rows are
            # kept under this version's header ("" for a figure it did not log).
            with open(self.path, "w", newline="") as f:
                out = csv.writer(f)
                out.writerow(self.fields)
                for r in rows:
                    out.writerow([r.get(k, "") for k in self.fields])

    def write(self, row):
        with open(self.path, "a", newline="") as f:
            csv.writer(f).writerow([row.get(k, "") for k in self.fields])

    def rows(self):
        return read_metrics(os.path.dirname(self.path))

    @staticmethod
    def progress(row, total_samples):
        done = min(1.0, row["samples"] / total_samples)
        bar = "#" * int(30 * done) + "-" * (30 - int(30 * done))
        ret, score = row.get("episode_return"), row.get("score")
        ret_text = "-" if ret is None else f"{ret:8.2f}"
        score_text = "-" if score is None else f"{score:.3f}"
        sys.stdout.write(
            f"\r[{bar}] {row['samples']:>10,d}/{total_samples:,d} samples "
            f"{row['samples_per_s']:7.0f}/s  iter {row['iteration']:4d}  return {ret_text}  "
            f"score {score_text}   ")
        sys.stdout.flush()

    def plot(self, out_png, title):
        """Return, episode length, the sport's score and each reward term over samples: the
        panels that have data (returned, by name)."""
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        rows = self.rows()
        if not rows:
            return []
        x = [float(r["samples"]) for r in rows]
        names = ["episode_return", "episode_length", "score", "win_rate", "touch_rate"] + [
            f for f in self.fields if f.startswith("term_")]
        # Only the figures this run has: a ball return has no win rate, a match no touch rate.
        series = {}
        for name in names:
            pts = [(xi, float(r[name])) for xi, r in zip(x, rows)
                   if r.get(name) not in ("", None)]
            if pts:
                series[name] = pts
        cols = 3
        nrows = max(1, (len(series) + cols - 1) // cols)
        fig, axes = plt.subplots(nrows, cols, figsize=(4.2 * cols, 2.8 * nrows), squeeze=False)
        for ax, (name, pts) in zip(axes.flat, series.items()):
            xs, ys = zip(*pts)
            ax.plot(xs, ys, lw=0.6, alpha=0.35)
            # Each iteration ends few episodes: a moving mean over ~1/40 of the run shows the
            # trend.
            w = max(1, len(ys) // 40)
            smooth = [sum(ys[max(0, i - w + 1):i + 1]) / len(ys[max(0, i - w + 1):i + 1])
                      for i in range(len(ys))]
            ax.plot(xs, smooth, lw=1.6, color="C1")
            ax.set_title(name.replace("term_", "reward term: "), fontsize=9)
            ax.set_xlabel("samples", fontsize=8)
            ax.tick_params(labelsize=7)
            ax.grid(alpha=0.3)
        for ax in list(axes.flat)[len(series):]:
            ax.axis("off")
        fig.suptitle(title, fontsize=10)
        fig.tight_layout()
        fig.savefig(out_png, dpi=90)
        plt.close(fig)
        return list(series)
