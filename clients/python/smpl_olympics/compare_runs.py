"""Did two runs of the same command give the same result? Compares two run folders.

    python3 -m smpl_olympics.compare_runs runs/a runs/b

- every snapshot (snapshots/*.safetensors): the same files on both sides, each tensor's name,
  dtype, shape and bytes identical (bit for bit), the metadata identical but for `policy_id`
  (the trainer writes the run folder's name there);
- metrics.csv: the same rows and columns, every value identical but for the wall-time columns
  (`wall_s`, `samples_per_s`); the `score` and `win_rate` columns count the results that
  arrived during an iteration, so a loaded machine can move one into the next row: those are
  reported separately and do not fail the comparison unless --strict;
- evaluation.json and evaluation.md (when both runs were evaluated): byte-identical.

Prints what differs and exits 1 if anything that should be deterministic does (docs/training.md,
"Reproducing a result").
"""
import argparse
import csv
import json
import os
import struct
import sys

WALL_TIME_COLUMNS = ("wall_s", "samples_per_s")
ARRIVAL_COLUMNS = ("score", "win_rate")  # results counted as they arrive: load-dependent rows
NAMED_AFTER_THE_FOLDER = ("policy_id",)


def read_safetensors(path):
    """{name: (dtype, shape, bytes)}, metadata: the file's tensors as stored, without numpy."""
    with open(path, "rb") as f:
        data = f.read()
    (size,) = struct.unpack("<Q", data[:8])
    header = json.loads(data[8:8 + size])
    body = data[8 + size:]
    metadata = header.pop("__metadata__", {})
    tensors = {name: (t["dtype"], tuple(t["shape"]), body[t["data_offsets"][0]:t["data_offsets"][1]])
               for name, t in header.items()}
    return tensors, metadata


def compare_snapshots(a, b):
    problems = []
    folder_a, folder_b = os.path.join(a, "snapshots"), os.path.join(b, "snapshots")
    names_a = sorted(n for n in os.listdir(folder_a) if n.endswith(".safetensors"))
    names_b = sorted(n for n in os.listdir(folder_b) if n.endswith(".safetensors"))
    if names_a != names_b:
        problems.append(f"snapshots differ in name: only in {a}: {sorted(set(names_a) - set(names_b))}, "
                        f"only in {b}: {sorted(set(names_b) - set(names_a))}")
    tensors = 0
    for name in sorted(set(names_a) & set(names_b)):
        ta, ma = read_safetensors(os.path.join(folder_a, name))
        tb, mb = read_safetensors(os.path.join(folder_b, name))
        if sorted(ta) != sorted(tb):
            problems.append(f"{name}: tensors {sorted(ta)} against {sorted(tb)}")
        for t in sorted(set(ta) & set(tb)):
            tensors += 1
            if ta[t][:2] != tb[t][:2]:
                problems.append(f"{name} {t}: dtype/shape {ta[t][:2]} against {tb[t][:2]}")
            elif ta[t][2] != tb[t][2]:
                problems.append(f"{name} {t}: the values differ")
        for key in sorted(set(ma) | set(mb)):
            if key not in NAMED_AFTER_THE_FOLDER and ma.get(key) != mb.get(key):
                problems.append(f"{name} metadata {key}: {ma.get(key)!r} against {mb.get(key)!r}")
    return problems, f"{len(set(names_a) & set(names_b))} snapshots, {tensors} tensors"


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def compare_metrics(a, b):
    """(problems, arrival differences, what was compared)."""
    rows_a, rows_b = read_csv(os.path.join(a, "metrics.csv")), read_csv(os.path.join(b, "metrics.csv"))
    problems, arrivals = [], []
    if len(rows_a) != len(rows_b):
        problems.append(f"metrics.csv: {len(rows_a)} rows against {len(rows_b)}")
    if rows_a and rows_b and list(rows_a[0]) != list(rows_b[0]):
        problems.append(f"metrics.csv: columns {list(rows_a[0])} against {list(rows_b[0])}")
    for ra, rb in zip(rows_a, rows_b):
        for column in ra:
            if column in WALL_TIME_COLUMNS or ra.get(column) == rb.get(column):
                continue
            where = f"metrics.csv iteration {ra.get('iteration')} {column}: {ra[column]} against {rb.get(column)}"
            (arrivals if column in ARRIVAL_COLUMNS else problems).append(where)
    return problems, arrivals, f"{min(len(rows_a), len(rows_b))} metrics rows"


def compare_evaluations(a, b):
    problems, compared = [], []
    for name in ("evaluation.json", "evaluation.md"):
        pa, pb = os.path.join(a, name), os.path.join(b, name)
        if not os.path.exists(pa) and not os.path.exists(pb):
            continue
        if not (os.path.exists(pa) and os.path.exists(pb)):
            problems.append(f"{name}: only in {a if os.path.exists(pa) else b}")
            continue
        with open(pa, "rb") as fa, open(pb, "rb") as fb:
            if fa.read() != fb.read():
                problems.append(f"{name}: the files differ")
        compared.append(name)
    return problems, " and ".join(compared) or "no evaluation"


def compare(a, b, strict=False):
    """(problems, notes, summary) for run folders a and b."""
    problems, notes, done = [], [], []
    p, what = compare_snapshots(a, b)
    problems += p
    done.append(what)
    p, arrivals, what = compare_metrics(a, b)
    problems += p + (arrivals if strict else [])
    notes += [] if strict else arrivals
    done.append(what)
    p, what = compare_evaluations(a, b)
    problems += p
    done.append(what)
    return problems, notes, ", ".join(done)


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m smpl_olympics.compare_runs", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run_a")
    p.add_argument("run_b")
    p.add_argument("--strict", action="store_true",
                   help="also fail on the score/win_rate columns of metrics.csv")
    args = p.parse_args(argv)
    for run in (args.run_a, args.run_b):
        if not os.path.isdir(os.path.join(run, "snapshots")) or not os.path.exists(
                os.path.join(run, "metrics.csv")):
            sys.exit(f"{run}: not a run folder (no snapshots/ or metrics.csv): give two --run folders")
    problems, notes, summary = compare(args.run_a, args.run_b, args.strict)
    for note in notes:
        print("varies (results counted as they arrived):", note)
    for problem in problems:
        print("DIFFERS:", problem)
    print(("identical: " if not problems else f"{len(problems)} differences in: ") + summary +
          " (wall-time columns and policy_id not compared)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
