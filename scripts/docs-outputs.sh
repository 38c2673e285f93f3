#!/usr/bin/env bash
# Refreshes every output, figure and timing the documentation quotes, so the docs can be
# regenerated instead of drifting:
#   docs/guide/output/<command>.txt   each guide page's example commands and what they printed
#   docs/figures/*.png                the figures of the guide pages
#   docs/reference/timings.md         machine, example wall times, run stages, benchmarks, test times
# and copies each output file into its guide page, between the markers
#   <!-- begin output NAME -->  ...  <!-- end output -->
#
# Usage: bash scripts/docs-outputs.sh [BINARY]      (default ./build/geartrib; run from anywhere)
# Environment:
#   GEARTRIB_BENCH   the benchmark binary (default: tests/geartrib_bench beside BINARY, else
#                    ./build/tests/geartrib_bench); without one the benchmark section says so
#   SKIP_BENCH=1     leave out the benchmarks (about a minute, most of it the 2^18-element reference)
#   SKIP_FEM=1       leave out the CalculiX example (15-100 s depending on the machine)
# Needs /usr/bin/python3 with h5py and matplotlib (scripts/setup.sh installs them).
# Takes about two to four minutes on two cores; the timing page records the machine and the load.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${1:-$root/build/geartrib}"
[[ "$bin" = /* ]] || bin="$(pwd)/$bin"
[[ -x "$bin" ]] || { echo "docs-outputs: no executable at $bin (build first: bash scripts/setup.sh)" >&2; exit 2; }
py=/usr/bin/python3
out="$root/docs/guide/output"
fig="$root/docs/figures"
mkdir -p "$out" "$fig" "$root/docs/reference"

# The examples run in a scratch folder that sees the repository's cases, so the commands read as
# a user types them from the source tree and their files do not land in it.
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for d in gears materials lubricants validation scripts examples; do ln -s "$root/$d" "$work/$d"; done
cd "$work"

times="$work/.times.tsv"   # page, command, seconds
: > "$times"

# The command as a user would type it: arguments with spaces in double quotes.
shown() {
  local a s=""
  for a in "$@"; do
    if [[ "$a" == *" "* ]]; then s+=" \"$a\""; else s+=" $a"; fi
  done
  echo "${s# }"
}
# ex PAGE ARGS...: runs `geartrib ARGS` in the scratch folder, appends "$ geartrib ARGS" and what
# it printed (standard output and error) to docs/guide/output/PAGE.txt, records the wall time.
ex() {
  local page="$1"; shift
  local t0 t1 rc=0 cmd
  cmd="geartrib $(shown "$@")"
  printf '$ %s\n' "$cmd" >> "$out/$page.txt"
  t0=$(date +%s%N)
  "$bin" "$@" >> "$out/$page.txt" 2>&1 || rc=$?
  t1=$(date +%s%N)
  [[ $rc -eq 0 ]] || printf '(exit status %d)\n' "$rc" >> "$out/$page.txt"
  printf '%s\t%s\t%s\n' "$page" "$cmd" "$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.4f", (b - a) / 1e9}')" >> "$times"
  echo "docs-outputs: $page: $cmd" >&2
}
# sh_ex PAGE 'COMMAND': a shell command, shown as typed (plots, file excerpts).
sh_ex() {
  local page="$1" cmd="$2" rc=0
  printf '$ %s\n' "$cmd" >> "$out/$page.txt"
  bash -c "$cmd" >> "$out/$page.txt" 2>&1 || rc=$?
  [[ $rc -eq 0 ]] || printf '(exit status %d)\n' "$rc" >> "$out/$page.txt"
}
fresh() { : > "$out/$1.txt"; }
blank() { echo >> "$out/$1.txt"; }

# ---------------------------------------------------------------------------------------------
fresh run
ex run run -o m6z30.h5 --csv m6z30.csv
blank run
sh_ex run "/usr/bin/python3 scripts/plot_mesh.py m6z30.h5 plots/ && ls plots | head -5"
cp plots/overview.png "$fig/run-overview.png"
cp plots/lubrication.png "$fig/run-lubrication.png"
blank run
ex run run gears/m6z30-dry.toml -o m6z30-dry.h5

fresh own-pair
ex own-pair run examples/fzg-c-from-blank.toml -o fzg-c.h5 --csv fzg-c.csv
blank own-pair
sh_ex own-pair "/usr/bin/python3 scripts/plot_mesh.py fzg-c.h5 plots-fzg-c/"
cp plots-fzg-c/lubrication.png "$fig/own-pair-lubrication.png"

fresh run-deterministic
ex run-deterministic run gears/m6z30-deterministic.toml -o det.h5
blank run-deterministic
sh_ex run-deterministic "/usr/bin/python3 scripts/plot_deterministic.py det.h5 -o det"
cp det-path.png "$fig/deterministic-path.png"
cp det-pressure.png "$fig/deterministic-pressure.png"
blank run-deterministic
ex run-deterministic run gears/m6z30-deterministic.toml --set running_in.meshes=40 --set positions=101 --set element_size=1um -o runin.h5
sh_ex run-deterministic "/usr/bin/python3 scripts/plot_deterministic.py runin.h5 -o runin"
cp runin-running-in.png "$fig/deterministic-running-in.png"

fresh run-measured-patch
ex run-measured-patch run gears/m6z30-measured.toml --fidelity deterministic -o measured-det.h5
# The table of quantities (as in run-deterministic) left out of this page's excerpt.
sed -i '/^quantity  /,/^statistical_flag_deep_separation/c\(the table of quantities along the path, as above, left out here)' "$out/run-measured-patch.txt"
blank run-measured-patch
sh_ex run-measured-patch "/usr/bin/python3 -c \"import h5py; a = h5py.File('measured-det.h5', 'r')['synthesis/pinion'].attrs; [print(k, '=', a[k].decode() if isinstance(a[k], bytes) else a[k]) for k in sorted(a)]\""

fresh sweep
# columns FILE COLUMN...: selected columns of a sweep's CSV, numbers to 4 digits.
columns() {
  $py - "$@" >> "$out/sweep.txt" <<'PY'
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
cols = sys.argv[2:]
print("  ".join(f"{c:>{max(len(c), 10)}}" for c in cols))
for r in rows:
    print("  ".join(f"{(r[c] if c in ('status', 'point') else format(float(r[c]), '.4g')):>{max(len(c), 10)}}" for c in cols))
PY
}
ex sweep sweep --set module=4mm,6mm,8mm --set face_width=40mm:80mm:3 --set rq=0.2um,0.8um -o sweep.h5 --csv sweep.csv
blank sweep
echo "(selected columns of sweep.csv)" >> "$out/sweep.txt"
columns sweep.csv point module face_width rq status hertz_p0_Pa_max real_area_ratio_min mesh_power_loss_W min_iso_lambda_gf
blank sweep
sh_ex sweep "/usr/bin/python3 scripts/plot_design_sweep.py sweep.h5 --quantity hertz_p0_Pa_max,mesh_power_loss_W --at rq=2e-7 -o p0.png"
cp p0.png "$fig/sweep-hertz-p0.png"
blank sweep
echo "(torque x roughness: the mesh-level values of the lubricated runs, one column each)" >> "$out/sweep.txt"
ex sweep sweep --set torque=500Nm,1000Nm,2000Nm --set ra=0.4um,0.8um -o torque.h5 --csv torque.csv
blank sweep
columns torque.csv torque ra mesh_power_loss_W pair_power_loss_W_mean tooth_friction_efficiency gear_loss_factor_path bulk_temperature_K min_iso_lambda_gf
blank sweep
sh_ex sweep "/usr/bin/python3 scripts/plot_design_sweep.py torque.h5 -o torque.png"
cp torque.png "$fig/sweep-mesh-level.png"
blank sweep
echo "(a Stribeck curve: the lubricated default case over speed, ground flanks, bulk temperature fixed)" >> "$out/sweep.txt"
ex sweep sweep --set speed=1rpm,3rpm,10rpm,30rpm,100rpm,300rpm,1000rpm,3000rpm,10000rpm --set ra=0.2um --set bulk_temperature=80degC --set positions=41 -o stribeck.h5 --csv stribeck.csv
sh_ex sweep "/usr/bin/python3 scripts/plot_stribeck.py stribeck.csv stribeck.png"
cp stribeck.png "$fig/stribeck.png"

fresh tradeoff
ex tradeoff tradeoff --knob positions --knob height_points --knob table_points --knob strip_points -o tradeoff.png
cp tradeoff.png "$fig/tradeoff.png"

fresh kinematics
ex kinematics kinematics --summary
blank kinematics
ex kinematics kinematics

fresh dynamics
ex dynamics dynamics --speed 1000rpm -o cycle.txt
sh_ex dynamics "head -4 cycle.txt"
blank dynamics
ex dynamics dynamics --speed-sweep 500rpm:9000rpm:18
"$bin" dynamics --speed-sweep 100rpm:9000rpm:179 --csv -o speeds.csv 2> speeds.log
fn=$(sed -n 's/.*natural frequency \([0-9.]*\) Hz.*/\1/p' speeds.log | head -1)
$py "$root/scripts/plot_speed_sweep.py" speeds.csv "$fig/dynamics-speed-sweep.png" $fn > /dev/null

fresh tooth-contact
ex tooth-contact kinematics gears/m6z30-relief.toml
blank tooth-contact
ex tooth-contact kinematics gears/m6z30-relief.toml --summary
sed -i '/^ *reference_center_distance_m/,/^ *mean_mesh_stiffness_over_iso_c_gamma_alpha/c\(the geometry and stiffness rows, as in kinematics --summary, left out here)' "$out/tooth-contact.txt"
blank tooth-contact
ex tooth-contact run gears/m6z30-relief.toml -o relief.h5
sed -i '/^quantity  /,/^wear_depth_wheel_m/c\(the table of quantities along the path, as in geartrib run, left out here)' "$out/tooth-contact.txt"
blank tooth-contact
ex tooth-contact sweep gears/m6z30-relief.toml --set tip_relief=0um:30um:7 --set torque=200Nm:2000Nm:10 -o harris.h5
sh_ex tooth-contact "/usr/bin/python3 scripts/plot_design_sweep.py harris.h5 --quantity transmission_error_peak_to_peak_m --x torque --lines tip_relief -o harris.png"
cp harris.png "$fig/tooth-contact-harris-map.png"
blank tooth-contact
ex tooth-contact dynamics gears/m6z30-relief.toml --speed-sweep 500rpm:9000rpm:18

fresh ratings
ex ratings rate gears/fzg-c.toml --set fzg_test=PT-C
blank ratings
ex ratings sweep gears/m6z30.toml --set module=4mm:7mm:4 --set face_width=60mm,80mm,100mm --set ra=0.4um,0.8um -o design.h5
sh_ex ratings "/usr/bin/python3 scripts/plot_design_sweep.py design.h5 --quantity ratings --x module --lines face_width -o design.png"
cp design.png "$fig/ratings-design-sweep.png"
blank ratings
ex ratings run gears/m6z30.toml -o m6z30.h5 --report
sed -i '/^quantity  /,/^wear_depth_wheel_m/c\(the table of quantities along the path, as in geartrib run, left out here)' "$out/ratings.txt"

fresh asperity
ex asperity asperity --summary
blank asperity
ex asperity asperity --model kogut-etsion --delta-star 1,2,6,10
blank asperity
ex asperity asperity --contact side --mu 0.1 --delta-star 0.5,2,10

fresh multi-asperity
ex multi-asperity multi-asperity --layout HLH --height-step 3 --spacing 0.5um --delta-pc 0.5797nm

fresh ehl
ex ehl ehl --load 1e6 --radius 15.4mm --speed 5m/s --modulus 113GPa --viscosity 0.05 --alpha 2e-8
blank ehl
ex ehl ehl --materials materials/steel-45.toml --lubricant lubricants/mineral-vg100.toml --oil-temperature 80degC --load 3e5 --radius 10mm --speed 5m/s --slide-roll 0.4 --waviness 50nm,100um -o ehl.h5

fresh surface
ex surface surface generate hobbed -o hob.xyz --tip-radius "6.6 um" --noise "2 nm"
ex surface surface stats hob.xyz
blank surface
ex surface surface asperities hob.xyz --cylinders
blank surface
ex surface surface generate self-affine -o upper.h5 --seed 1
ex surface surface generate self-affine -o lower.h5 --seed 2
ex surface surface equivalent upper.h5 lower.h5 -o equivalent.h5
$py "$root/scripts/plot_surface.py" equivalent.h5 "$fig/surface-equivalent.png" > /dev/null

fresh fem
if [[ "${SKIP_FEM:-0}" == 1 ]]; then
  echo "(left out: SKIP_FEM=1)" >> "$out/fem.txt"
elif command -v ccx > /dev/null; then
  ex fem fem single-asperity --material elastic --delta-star 1,2 --refine 10
else
  echo "(ccx not installed on the machine that refreshed this: the example was not run)" >> "$out/fem.txt"
fi

fresh fit
ex fit fit --list kogut-etsion
blank fit
ex fit fit --model kogut-etsion --data validation/fem-reference/ccx-perfectly-plastic.csv \
  --free load_coefficient_1,load_exponent_1,area_coefficient_1,area_exponent_1 --observe load_star,area_star \
  -o ke-ccx.toml --report ke-ccx-report.txt
sh_ex fit "cat ke-ccx.toml"

fresh case
help_text="$("$bin" --help 2>/dev/null || true)"  # whole, then grep: no SIGPIPE under pipefail
if grep -qE '^ +case +' <<< "$help_text"; then
  ex case case --set module=5mm --set rq=0.4um
else
  echo "(this binary has no \`case\` command yet: rerun the script with a build that has it)" >> "$out/case.txt"
fi

fresh version
ex version version

# ---------------------------------------------------------------------------------------------
# Timings: the main job's stages on three cases (from each file's /meta), the benchmarks, the
# tests' times as CTest last recorded them.
"$bin" run -q -o t-default.h5 > /dev/null 2>&1
"$bin" run -q --set fidelity=coupled -o t-coupled.h5 > /dev/null 2>&1
"$bin" run -q validation/mesh-cycle-m6z30/superfinished.toml -o t-superfinished.h5 > /dev/null 2>&1
"$bin" run -q gears/m6z30-deterministic.toml --set threads=1 -o t-deterministic.h5 > /dev/null 2>&1

bench="${GEARTRIB_BENCH:-}"
if [[ -z "$bench" ]]; then
  for b in "$(dirname "$bin")/tests/geartrib_bench" "$root/build/tests/geartrib_bench"; do
    [[ -x "$b" ]] && { bench="$b"; break; }
  done
fi
bench_note=""
if [[ "${SKIP_BENCH:-0}" == 1 ]]; then
  bench_note="left out (SKIP_BENCH=1)"
elif [[ -n "$bench" && -x "$bench" ]]; then
  echo "docs-outputs: benchmarks ($bench)" >&2
  # The 2^18-element grids (BEM ~40 s, Hertz ~20 s) and the 4096^2 surface are left out; the
  # BEM errors are still against the 2^18 reference, which the benchmark computes once.
  "$bench" --benchmark_filter='^(evaluate|side|steady_cycle|surface_statistics|gw_|strip_|cycle|path_load_sharing|multi_asperity/(4096|16384|65536)|hertz_line_contact/(4096|16384|65536)|self_affine_generation/(256|1024))' \
           --benchmark_min_time=0.1 --benchmark_format=json > bench.json 2> /dev/null || bench_note="the benchmark binary failed"
else
  bench_note="no geartrib_bench found (it is built with the tests: bash scripts/setup.sh test, or set GEARTRIB_BENCH)"
fi

ctest_dir="$root/build"
$py - "$root" "$bin" "$times" "$bench_note" "$ctest_dir" <<'PY'
import json, os, re, subprocess, sys, time
import h5py

root, binary, times_path, bench_note, ctest_dir = sys.argv[1:6]
lines = []
w = lines.append

def fmt_time(s):
    if s >= 1: return f"{s:.3g} s"
    if s >= 1e-3: return f"{s * 1e3:.3g} ms"
    if s >= 1e-6: return f"{s * 1e6:.3g} us"
    return f"{s * 1e9:.3g} ns"

cpu = "unknown CPU"
try:
    for l in open("/proc/cpuinfo"):
        if l.startswith("model name"):
            cpu = l.split(":", 1)[1].strip(); break
except OSError:
    pass
version = subprocess.run([binary, "version"], capture_output=True, text=True).stdout.splitlines()
version = version[0] if version else "geartrib (version unknown)"
load = open("/proc/loadavg").read().split()[:3] if os.path.exists("/proc/loadavg") else ["?"] * 3

w("# Timings")
w("")
w("Generated by `scripts/docs-outputs.sh`; do not edit by hand: rerun the script (with a Release")
w("build) to refresh every number on this page. Times depend on the machine and on what else runs")
w("on it: compare them with each other, not with another machine's.")
w("")
w(f"- Machine: {os.cpu_count()} cores, {cpu}; load average {' '.join(load)} when the timings were taken")
w(f"- Binary: `{version}`; refreshed {time.strftime('%Y-%m-%d %H:%M %Z')}")
w("")

w("## The guide's examples (wall time of the whole process)")
w("")
w("| page | command | time |")
w("|---|---|---|")
for l in open(times_path):
    page, cmd, s = l.rstrip("\n").split("\t")
    if len(cmd) > 90: cmd = cmd[:87] + "..."
    guide = page if os.path.exists(os.path.join(root, "docs/guide", page + ".md")) else page.split("-")[0]
    w(f"| [{page}](../guide/{guide}.md) | `{cmd}` | {fmt_time(float(s))} |")
w("")

w("## The main job's stages (`geartrib run`, from each file's `/meta/stage_seconds`)")
w("")
w("| case | stages | computation |")
w("|---|---|---|")
for label, f in (("`gears/m6z30.toml` (uncoupled, 201 positions)", "t-default.h5"),
                 ("the same, `--set fidelity=coupled` (128 nodes)", "t-coupled.h5"),
                 ("`validation/mesh-cycle-m6z30/superfinished.toml` (partly elastic)", "t-superfinished.h5"),
                 ("`gears/m6z30-deterministic.toml` (deterministic, 0.5 um elements, one thread)",
                  "t-deterministic.h5")):
    with h5py.File(f, "r") as h:
        names = [n.decode() if isinstance(n, bytes) else n for n in h["meta/stage_names"][()]]
        secs = list(h["meta/stage_seconds"][()])
    stages = "; ".join(f"{n} {fmt_time(s)}" for n, s in zip(names, secs))
    w(f"| {label} | {stages} | {fmt_time(sum(secs))} |")
w("")
w("The whole process also loads the case and writes the file: see the `run` row above.")
w("")

w("## Benchmarks (`geartrib_bench`, Google Benchmark)")
w("")
if bench_note or not os.path.exists("bench.json"):
    w(f"Not measured in this refresh: {bench_note or 'no benchmark output'}.")
else:
    data = json.load(open("bench.json"))
    rows = {b["name"]: b for b in data["benchmarks"] if b.get("run_type", "iteration") == "iteration"}
    unit = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
    t = lambda b: b["real_time"] * unit[b["time_unit"]]
    def table(title, note, header, pick):
        sel = [(n, b) for n, b in rows.items() if pick(n)]
        if not sel: return
        w(f"### {title}")
        w("")
        if note: w(note); w("")
        w("| " + " | ".join(header) + " |")
        w("|" + "---|" * len(header))
        for n, b in sel:
            w("| " + " | ".join(c(n, b) for c in header_fns[title]) + " |")
        w("")
    g = lambda key, f="{:.3g}": (lambda n, b: f.format(b[key]) if key in b else "")
    name = lambda n, b: f"`{n}`"
    tm = lambda n, b: fmt_time(t(b))
    header_fns = {}
    def add(title, note, cols, pick):
        header_fns[title] = [c for _, c in cols]
        table(title, note, [h for h, _ in cols], pick)
    add("One asperity", "`evaluate/*_load_area`: load, area and plastic share only; `*_full`: with the pressure profile "
        "and the von Mises maximum (the maximisation of closed forms, no table); `side`: one side-contact evaluation (elliptical Hertz).",
        [("benchmark", name), ("time", tm)], lambda n: n.startswith(("evaluate/", "side")))
    add("The mesh cycle's kernels (seed case)", "Summit-height quadrature at one separation (points), the "
        "pressure-separation table (points per sigma), the separation inversion, one strip across the Hertz "
        "contact (uncoupled points, coupled nodes), the highest asperity's stresses, and the whole cycle of "
        "201 positions (`coupled:0` uncoupled, `coupled:1` coupled); the lubricated cycle and its path stage alone "
        "under each load sharing (`sharing:` 0 ISO, 1 stiffness, 2 compatibility with gears/m6z30-relief.toml's "
        "reliefs, 3 compatibility without them).",
        [("benchmark", name), ("time", tm)], lambda n: n.startswith(("gw_", "strip_", "cycle", "path_load_sharing")))
    add("Boundary elements: the grid's trade (HLH study, h_m = 2 delta_pc, 0.5 um, 6 delta_pc)",
        "Complementarity error 1e-10. Errors: the largest per-asperity load and contact-width difference "
        "from the 2^18-element grid.",
        [("benchmark", name), ("time", tm), ("iterations", g("iterations", "{:.0f}")),
         ("load error", g("error_load")), ("width error", g("error_width"))],
        lambda n: n.startswith("multi_asperity/"))
    add("Boundary elements: Hertz line contact (Polonsky-Keer, load control)", "Errors against Hertz.",
        [("benchmark", name), ("time", tm), ("iterations", g("iterations", "{:.0f}")),
         ("peak error", g("error_peak")), ("half-width error", g("error_half_width"))],
        lambda n: n.startswith("hertz_line_contact/"))
    add("Mesh dynamics: the steady cycle at 1000 rpm", "Last number: -log10 of the relative tolerance; "
        "error: the dynamic factor against the tightest run.",
        [("benchmark", name), ("time", tm), ("cycles", g("cycles", "{:.0f}")), ("steps", g("steps", "{:.0f}")),
         ("error", g("error"))], lambda n: n.startswith("steady_cycle/"))
    add("Topography", "`surface_statistics_resampled/k`: statistics of a 1024 x 1024 surface at 0.25 um "
        "resampled to k times the spacing, errors against the full resolution; `self_affine_generation/n`: "
        "an n x n surface.",
        [("benchmark", name), ("time", tm), ("m2 error", g("err_m2")), ("m4 error", g("err_m4")),
         ("summit density error", g("err_summit_density"))],
        lambda n: n.startswith(("surface_statistics", "self_affine")))
    ctx = data.get("context", {})
    w(f"Benchmark library built as {ctx.get('library_build_type', '?')} (the library's own build, not geartrib's); "
      f"each benchmark ran for at least 0.1 s. The 2^18-element grids are left out to keep the refresh short; "
      f"`validation/tradeoff/README.md` lists them.")
w("")

w("## Tests (as CTest last recorded them in `build/`)")
w("")
cost = os.path.join(ctest_dir, "Testing/Temporary/CTestCostData.txt")
import shutil
if not os.path.exists(cost) or not shutil.which("ctest"):
    w("No `build/Testing/Temporary/CTestCostData.txt`: run the tests first (`bash scripts/setup.sh test`).")
else:
    seconds = {}
    for l in open(cost):
        p = l.rsplit(" ", 2)
        if len(p) == 3:
            try: seconds[p[0]] = float(p[2])
            except ValueError: pass
    def listed(*selection):
        cmd = ["ctest", "--test-dir", ctest_dir, "-N", *selection]
        r = subprocess.run(cmd, capture_output=True, text=True)
        names = []
        for l in r.stdout.splitlines():
            m = re.match(r"\s*Test\s+#\d+: (.*)$", l)
            if m: names.append(re.sub(r"\s+# GetParam\(\).*$", "", m.group(1)).strip())
        return names
    w("CTest's running average per test (`CTestCostData.txt`), summed; one process at a time would take "
      "the sum, `ctest -j` less.")
    w("")
    w("| tests | count | total | slowest |")
    w("|---|---|---|---|")
    rows = [("default suite (`bash scripts/setup.sh test`: all but label `long`)", listed("-LE", "^long$"))]
    for label in ("extremes", "validation", "fem", "examples", "install", "python", "corpus", "long"):
        rows.append((f"label `{label}`", listed("-L", f"^{label}$")))
    for label, names in rows:
        known = [(seconds[n], n) for n in names if n in seconds]
        total = sum(s for s, _ in known)
        slow = ", ".join(f"{n} {fmt_time(s)}" for s, n in sorted(known, reverse=True)[:3])
        w(f"| {label} | {len(names)} | {fmt_time(total) if known else '-'} | {slow or '-'} |")
w("")
open(os.path.join(root, "docs/reference/timings.md"), "w").write("\n".join(lines).rstrip("\n") + "\n")
PY

# ---------------------------------------------------------------------------------------------
# Copy each output into its guide page between <!-- begin output NAME --> and <!-- end output -->.
$py - "$root/docs/guide" "$out" <<'PY'
import os, re, sys
guide, out = sys.argv[1:3]
pattern = re.compile(r"(<!-- begin output ([\w-]+) -->\n).*?(<!-- end output -->)", re.S)
for page in sorted(os.listdir(guide)):
    if not page.endswith(".md"): continue
    path = os.path.join(guide, page)
    text = open(path).read()
    def fill(m):
        body = open(os.path.join(out, m.group(2) + ".txt")).read().rstrip("\n")
        note = (f"*Real output, copied from `docs/guide/output/{m.group(2)}.txt` by `scripts/docs-outputs.sh`;"
                " rerun the script to refresh it.*")
        return f"{m.group(1)}{note}\n\n```text\n{body}\n```\n{m.group(3)}"
    new = pattern.sub(fill, text)
    if new != text: open(path, "w").write(new)
PY
echo "docs-outputs: wrote docs/guide/output/, docs/figures/, docs/reference/timings.md" >&2
