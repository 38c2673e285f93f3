#!/usr/bin/env bash
# The calculation report (geartrib report, run --report) opened in a real headless browser
# (Debian's chromium): it renders without errors, shows the safety factors the result file holds,
# its plots are drawn, and it loads nothing from outside itself. Usage: report_browser.sh GEARTRIB
# (from the source tree).
set -u
bin="$1"
py=/usr/bin/python3
fail=0
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
ok() { echo "ok   $1"; }
bad() { echo "FAIL $1"; fail=1; }
browser="$(command -v chromium || command -v chromium-browser || true)"
if [[ -z "$browser" ]]; then
  echo "FAIL no chromium: install Debian's chromium (scripts/setup.sh does)"; exit 1
fi

"$bin" run -q gears/m6z30.toml -o "$tmp/m6z30.h5" --report >/dev/null && [[ -s "$tmp/m6z30.html" ]] && ok run-report || bad run-report
"$bin" report "$tmp/m6z30.h5" -o "$tmp/again.html" && cmp -s "$tmp/m6z30.html" "$tmp/again.html" && ok report-equals-run-report ||
  bad report-equals-run-report
# Bad input: not a result file; nothing written.
echo "not hdf5" > "$tmp/bad.h5"
"$bin" report "$tmp/bad.h5" -o "$tmp/bad.html" 2>"$tmp/err"; rc=$?
[[ $rc -ne 0 && ! -e "$tmp/bad.html" ]] && grep -q "not an HDF5 file" "$tmp/err" && ok bad-input-nothing-written ||
  bad "bad-input-nothing-written (exit $rc: $(cat "$tmp/err"))"

# The browser: the DOM after rendering, and its console (errors and failed loads would show there).
# --no-sandbox: root in CI containers; a fresh profile each time.
render() {
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-extensions --user-data-dir="$tmp/profile" \
    --enable-logging=stderr --v=0 --virtual-time-budget=5000 --dump-dom "file://$1" 2>"$2"
}
render "$tmp/m6z30.html" "$tmp/console" > "$tmp/dom.html"; rc=$?
[[ $rc -eq 0 && -s "$tmp/dom.html" ]] && ok rendered || bad "rendered (exit $rc)"
# Console errors of the page itself (chromium's own dbus/GPU noise is not the page's).
if grep -E "CONSOLE|Uncaught|Failed to load|net::ERR" "$tmp/console" >/dev/null; then
  bad "console: $(grep -E "CONSOLE|Uncaught|Failed to load|net::ERR" "$tmp/console" | head -3)"
else
  ok no-console-errors
fi
"$py" - "$tmp/m6z30.h5" "$tmp/dom.html" <<'PY' && ok shows-the-safety-factors || bad shows-the-safety-factors
import html.parser, sys, h5py
f = h5py.File(sys.argv[1], "r")
dom = open(sys.argv[2]).read()

class Cells(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.rows, self.row, self.cell, self.svgs, self.polylines, self.external = [], None, None, 0, 0, []
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "tr": self.row = []
        if tag in ("td", "th"): self.cell = ""
        if tag == "svg": self.svgs += 1
        if tag == "polyline" and len(a.get("points", "").split()) > 10: self.polylines += 1
        for k in ("src", "href"):
            if k in a and not a[k].startswith("#"): self.external.append(a[k])
    def handle_endtag(self, tag):
        if tag in ("td", "th") and self.row is not None: self.row.append(self.cell.strip()); self.cell = None
        if tag == "tr" and self.row is not None: self.rows.append(self.row); self.row = None
    def handle_data(self, d):
        if self.cell is not None: self.cell += d

p = Cells(); p.feed(dom)
a = f["rating"].attrs
# The safety table: S_H and S_F of each gear as the file holds them (4 significant digits).
row = {r[0]: r[1:] for r in p.rows if r}
for label, names in (("SH pitting", ("S_H_pinion", "S_H_wheel")), ("SF tooth root", ("S_F_pinion", "S_F_wheel"))):
    cells = row[label]
    for cell, name in zip(cells, names):
        assert abs(float(cell) - a[name]) <= 5e-4 * a[name], (label, cell, a[name])
assert abs(float(row["SB scuffing, flash temperature"][0]) - a["S_B"]) <= 5e-4 * a["S_B"]
# Every factor of /rating appears in the factor table, in order.
symbols = [s.decode() for s in f["rating/symbol"][()]]
table = [r[0] for r in p.rows if len(r) == 6]
assert table[1:] == symbols, (len(table), len(symbols))
# The plots: one svg each with its curve drawn; nothing loaded from elsewhere.
assert p.svgs >= 6 and p.polylines >= 6, (p.svgs, p.polylines)
assert not p.external, p.external
# Engineering units and the gear data: the diameters of A and E on the pinion in mm.
assert "start of active profile" in dom and "1/min" in dom and "MPa" in dom
print("svgs", p.svgs, "factors", len(symbols))
PY

# A dry case (no lubrication, bending rated alone) renders too and says what was not rated.
"$bin" run -q gears/m6z30-dry.toml -o "$tmp/dry.h5" --set "rating.methods=[pitting, bending]" --report >/dev/null
render "$tmp/dry.html" "$tmp/console-dry" > "$tmp/dom-dry.html"
grep -q "not rated" "$tmp/dom-dry.html" && grep -q "a dry case" "$tmp/dom-dry.html" && ok dry-case || bad dry-case
exit $fail
