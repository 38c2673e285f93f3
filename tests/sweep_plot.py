#!/usr/bin/python3
"""scripts/plot_design_sweep.py on the sweeps users make: a torque x roughness sweep of the
lubricated default case plots its mesh-level values against torque with one line per Ra, each line
the table's numbers in engineering units; the axes come from the file (the HDF5 attribute, the
CSV's layout), never its text columns; a third axis gives panels, a fourth a refusal naming --at.

Usage: sweep_plot.py path/to/geartrib   (run from the source tree; python3-h5py, -matplotlib)
"""
import atexit
import importlib.util
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

spec = importlib.util.spec_from_file_location("plot_design_sweep", "scripts/plot_design_sweep.py")
plot_design_sweep = importlib.util.module_from_spec(spec)
spec.loader.exec_module(plot_design_sweep)

binary = sys.argv[1]
tmp = Path(tempfile.mkdtemp())
atexit.register(shutil.rmtree, tmp, True)


def sweep(name, *sets):
    args = [binary, "sweep", "-q", *(x for s in sets for x in ("--set", s)), "--set", "positions=21",
            "-o", tmp / f"{name}.h5", "--csv", tmp / f"{name}.csv"]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return tmp / f"{name}.h5", tmp / f"{name}.csv"


def check(name, ok, detail=""):
    print(("ok   " if ok else "FAIL ") + name + ("" if ok else f": {detail}"))
    return ok


passed = True
h5, csv = sweep("torque-ra", "torque=500Nm,1000Nm,2000Nm", "ra=0.4um,0.8um")
cols, units, axes = plot_design_sweep.read_table(str(h5))
passed &= check("axes-from-hdf5", axes == ["torque", "ra", "positions"], axes)
passed &= check("axes-from-csv-layout", plot_design_sweep.read_table(str(csv))[2] == axes)

fig = plot_design_sweep.plot(str(h5))
panels = [ax for ax in fig.axes if ax.get_visible()]
# The defaults: the mesh-level values present (no scuffing temperature: no safeties).
titles = [ax.get_title() for ax in panels]
passed &= check("default-quantities", titles == ["mesh power loss", "tooth friction efficiency",
                                                  "gear loss factor path", "bulk temperature", "min iso lambda gf"],
                titles)
passed &= check("title-fixed-values", fig._suptitle.get_text() == "positions = 21", fig._suptitle.get_text())
# One line per Ra value in every panel, x = torque [N m], y = the table's values (SI to engineering
# units: the bulk temperature in degC; the rest shown in their SI unit). Compared exactly: the
# script plots the table's numbers through one subtraction at most, done here the same way.
quantities = ["mesh_power_loss_W", "tooth_friction_efficiency", "gear_loss_factor_path", "bulk_temperature_K",
              "min_iso_lambda_gf"]
shift = {"bulk_temperature_K": -273.15}
lines_ok = True
for ax, q in zip(panels, quantities):
    lines = ax.get_lines()
    lines_ok &= len(lines) == 2
    for line, ra in zip(lines, (4e-7, 8e-7)):
        rows = sorted((i for i in range(len(cols["ra"])) if cols["ra"][i] == ra), key=lambda i: cols["torque"][i])
        lines_ok &= list(line.get_xdata()) == [500.0, 1000.0, 2000.0]
        lines_ok &= list(line.get_ydata()) == [cols[q][i] + shift.get(q, 0.0) for i in rows]
    lines_ok &= ax.get_xlabel() == "torque [N m]"
legend = [t.get_text() for t in panels[0].get_legend().get_texts()]
passed &= check("one-line-per-ra", lines_ok and legend == ["ra = 0.4 um", "ra = 0.8 um"], legend)
passed &= check("units", [ax.get_ylabel() for ax in panels] == ["[W]", "[-]", "[-]", "[degC]", "[-]"])
out = tmp / "torque-ra.png"
status = plot_design_sweep.main(["plot_design_sweep.py", str(csv), "--quantity", "hertz_p0_Pa_max", "-o", str(out)])
passed &= check("png-from-csv", status == 0 and out.stat().st_size > 0)

# A third axis: one column of panels per speed (in 1/min); a fourth: refused, naming --at.
h5, _ = sweep("three", "torque=500Nm,1000Nm", "ra=0.4um,0.8um", "speed=500rpm,1000rpm")
fig = plot_design_sweep.plot(str(h5), ["hertz_p0_Pa_max", "mesh_power_loss_W"])
titles = [ax.get_title() for ax in fig.axes]
passed &= check("small-multiples", titles == ["hertz p0, max (speed = 500 1/min)", "hertz p0, max (speed = 1000 1/min)",
                                              "mesh power loss (speed = 500 1/min)",
                                              "mesh power loss (speed = 1000 1/min)"], titles)
h5, _ = sweep("four", "torque=500Nm,1000Nm", "ra=0.4um,0.8um", "speed=500rpm,1000rpm", "face_width=60mm,80mm")
try:
    plot_design_sweep.plot(str(h5))
    passed &= check("four-axes-refused", False, "plotted")
except plot_design_sweep.PlotError as e:
    passed &= check("four-axes-refused", "--at face_width=" in str(e), e)
held = plot_design_sweep.plot(str(h5), ["hertz_p0_Pa_max"], at=["face_width=0.08"])
passed &= check("four-axes-held", held._suptitle.get_text() == "positions = 21; face_width = 80 mm",
                held._suptitle.get_text())

# A dry sweep: the contact's quantities by default, lengths in mm and um.
h5, _ = sweep("dry", "lubricant=none", "module=4mm,8mm", "rq=0.2um,0.8um")
fig = plot_design_sweep.plot(str(h5))
passed &= check("dry-defaults", [ax.get_title() for ax in fig.axes] ==
                ["hertz p0, max", "real area ratio, min", "plastic area fraction, max"])
passed &= check("dry-units", fig.axes[0].get_xlabel() == "module [mm]" and fig.axes[0].get_ylabel() == "[MPa]" and
                [t.get_text() for t in fig.axes[0].get_legend().get_texts()] == ["rq = 0.2 um", "rq = 0.8 um"])
sys.exit(0 if passed else 1)
