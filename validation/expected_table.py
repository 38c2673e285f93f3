"""Check a validation case's outputs against its stored, provenance-stamped expected table.

Shared by validation/seed-section3/check.py, validation/gear-m6z30/check.py and
validation/seed-section7/compare.py. A case script computes rows (key, quantity, model value and,
where the reference is read from a data file at run time, the reference value) and calls
check(); `--write` on the script's command line stores the model values instead.

expected.csv: '# ' provenance lines (what, command, geartrib version, source, date), then
    key,quantity,model,reference,tolerance,verdict,regression,reason
  key, quantity  name the row (the quantity carries its unit)
  model          the model's value when the table was written (a number, True/False or a text)
  reference      the published, seed or hand value ('' when there is none)
  tolerance      how far the model may be from the reference to agree: "=" (identical),
                 "X" (absolute, in the row's unit), "X%" (percent of the reference), "rel X"
  verdict        agrees:     the model must be within the tolerance of the reference
                 departs:    a documented departure (the reason says why); with a tolerance the
                             model must stay outside it (a departure that starts to agree is news:
                             update the README and the table); without one only the regression
                 regression: no reference to agree with; the regression alone
  regression     how far the model may move from its stored value (same grammar; '' for none)
  reason         why this tolerance, or why the model departs, and the reference's source
Every row is checked, and a reference read at run time must equal the stored one (so a changed
reference file fails rather than silently moving the target). Exit status of check(): 0 when every
row is as expected, 1 otherwise.
"""
import csv
import datetime
import os
import subprocess
import sys

COLUMNS = ["key", "quantity", "model", "reference", "tolerance", "verdict", "regression", "reason"]
VERDICTS = ("agrees", "departs", "regression")


def fmt(value):
    """The stored text of a value: numbers to 10 significant digits, the rest as text."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, (int, float)):
        return f"{value:.10g}"
    return str(value)


def _number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def within(value, target, spec):
    """True when value is within spec (the tolerance grammar above) of target; a text only equal to
    the same text, under any spec (a number's tolerance on a value that is not a number, such as
    "undefined", asks that it stay that text)."""
    spec = spec.strip()
    a, b = _number(fmt(value)), _number(fmt(target))
    if a is None or b is None:
        return a is None and b is None and fmt(value) == fmt(target)
    if spec == "=":
        return a == b
    d = abs(a - b)
    if spec.endswith("%"):
        return d <= float(spec[:-1]) / 100.0 * abs(b)
    if spec.startswith("rel "):
        return d <= float(spec[4:]) * abs(b)
    return d <= float(spec)


def read(path):
    """(provenance lines, rows as dicts) of an expected table."""
    with open(path) as f:
        lines = f.read().splitlines()
    head = [line for line in lines if line.startswith("#")]
    rows = list(csv.DictReader(line for line in lines if not line.startswith("#")))
    return head, rows


def binary_argument(argv, usage):
    """The geartrib binary a case script's command line names, made absolute; None after printing
    `usage` (the script's docstring) to standard error when none is named or an option stands in
    its place (the script then exits 2)."""
    if len(argv) < 2 or argv[1].startswith("-"):
        print(usage.strip(), file=sys.stderr)
        return None
    return os.path.abspath(argv[1])


def version(binary):
    try:
        out = subprocess.run([binary, "version"], capture_output=True, text=True, check=True).stdout
        return out.splitlines()[0].strip()
    except (OSError, subprocess.CalledProcessError, IndexError):
        return "unknown"


def source_revision():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    try:
        return subprocess.run(["git", "-C", root, "describe", "--always", "--dirty"], capture_output=True,
                               text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write(path, rows, binary, what, command):
    """Store the model values; keep the stored references, tolerances, verdicts and reasons."""
    old = {}
    if os.path.exists(path):
        for r in read(path)[1]:
            old[(r["key"], r["quantity"])] = r
    out = []
    for r in rows:
        k = (r["key"], r["quantity"])
        # A new row takes what the script proposes (reference, tolerance, verdict, regression, reason).
        kept = old.pop(k, None) or {"reference": fmt(r.get("reference")), "tolerance": r.get("tolerance", ""),
                                     "verdict": r.get("verdict", "regression"), "regression": r.get("regression", ""),
                                     "reason": r.get("reason", "")}
        out.append({"key": r["key"], "quantity": r["quantity"], "model": fmt(r["model"]),
                    "reference": fmt(r["reference"]) if r.get("reference") is not None else kept["reference"],
                    **{c: kept[c] for c in ("tolerance", "verdict", "regression", "reason")}})
    with open(path, "w", newline="") as f:
        f.write(f"# {what}\n")
        f.write(f"# command: {command}\n")
        f.write(f"# geartrib: {version(binary)} (source {source_revision()})\n")
        f.write(f"# written: {datetime.date.today().isoformat()} (model column; references, tolerances and reasons kept)\n")
        f.write("# columns: validation/expected_table.py\n")
        w = csv.DictWriter(f, fieldnames=COLUMNS, lineterminator="\n")
        w.writeheader()
        w.writerows(out)
    for k in old:
        print(f"dropped {k[0]} / {k[1]} (no longer computed)")
    print(f"wrote {path} ({len(out)} rows)")
    return 0


def check(rows, path, argv, binary, what, command):
    """Compare rows [{key, quantity, model, reference (or None)}] with the table at path, or write it."""
    if "--write" in argv:
        return write(path, rows, binary, what, command)
    head, expected = read(path)
    for line in head[:4]:
        print(line)
    got = {(r["key"], r["quantity"]): r for r in rows}
    bad = 0
    counts = {v: 0 for v in VERDICTS}
    print(f"{'key':<22} {'quantity':<44} {'reference':>14} {'model':>14} {'tolerance':>10}  {'verdict':<10} status")
    for e in expected:
        k = (e["key"], e["quantity"])
        problems = []
        r = got.pop(k, None)
        if e["verdict"] not in VERDICTS:
            problems.append(f"unknown verdict '{e['verdict']}'")
        if r is None:
            problems.append("not computed")
            model = ""
        else:
            model = r["model"]
            if r.get("reference") is not None and not within(r["reference"], e["reference"], "=" if _number(e["reference"]) is None else "rel 1e-9"):
                problems.append(f"reference read as {fmt(r['reference'])}, stored {e['reference']}: the reference data changed")
            if e["regression"] and not within(model, e["model"], e["regression"]):
                problems.append(f"moved from stored {e['model']} (regression {e['regression']})")
            if e["verdict"] == "agrees" and not e["tolerance"]:
                problems.append("agrees without a tolerance")
            elif e["verdict"] == "agrees" and not within(model, e["reference"], e["tolerance"]):
                problems.append("no longer agrees with the reference")
            if e["verdict"] == "departs" and e["tolerance"] and within(model, e["reference"], e["tolerance"]):
                problems.append("now agrees: a documented departure changed (update the README and this table)")
        counts[e["verdict"]] = counts.get(e["verdict"], 0) + 1
        bad += bool(problems)
        status = "ok" if not problems else "FAIL: " + "; ".join(problems)
        print(f"{e['key']:<22} {e['quantity']:<44} {e['reference']:>14} {fmt(model):>14} {e['tolerance']:>10}  "
              f"{e['verdict']:<10} {status}")
    for k in got:
        print(f"{k[0]:<22} {k[1]:<44} FAIL: computed but not in {os.path.basename(path)} (--write to store it)")
        bad += 1
    print(f"{len(expected)} rows ({counts['agrees']} agree, {counts['departs']} documented departures, "
          f"{counts['regression']} regression only): {bad} failed")
    return 1 if bad else 0


if __name__ == "__main__":
    print(__doc__.strip(), file=sys.stderr)
    sys.exit(2)
