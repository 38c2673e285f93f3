#!/usr/bin/python3
"""The model's gear-mean friction on the FZG C gear against the levels measured on FZG rigs, with
the gear-mean laws beside it, and its trends against load, speed and roughness.

Usage: validation/friction-fzg/check.py GEARTRIB [--write] [--plot OUT.png]

Runs validation/fzg-c-lubricated/fzg-c-lubricated.toml (FZG C, b 14 mm) with `--set` changes:
ground flanks Ra 0.3 um, 8.3 m/s (2175 rpm), oil 90 degC, load stage 9 (302 N m, 0.5 m lever arm),
four shipped oils (FVA 3 and MINR mineral, PAOR PAO, ESTR ester), and sweeps of load stage, speed
and roughness on FVA 3. The model's gear-mean friction is the FZG power-loss test's own
definition, mu_mz = P_loss/(P_in H_V) (`mesh_mean_friction`, with the path's H_V). The references
are measured levels (README.md): mineral oil about 0.045 on the FZG rig and esters at 0.6-1.0 of
mineral (DGMK project summary, Doleschel et al.); about 0.065 at the lowest speed on the FZG C_mod
gear (Hinterstoisser 2014, via Arana et al. 2019). Rows against expected.csv; --plot draws the
friction against load stage, speed and Ra with the gear-mean laws beside it.
"""
import os
import subprocess
import sys
import tempfile

import h5py

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
sys.dont_write_bytecode = True
import expected_table  # noqa: E402

CASE = "validation/fzg-c-lubricated/fzg-c-lubricated.toml"
BASE = ["ra=0.3um", "speed=2175rpm", "oil_temperature=90degC"]
OILS = {"FVA 3 (mineral VG 100)": "../../lubricants/fva3.toml",
        "MINR (mineral VG 320)": "../../lubricants/mineral-vg320-minr.toml",
        "PAOR (PAO VG 320)": "../../lubricants/pao-vg320-paor.toml",
        "ESTR (ester VG 320)": "../../lubricants/ester-vg320-estr.toml"}
STAGES = {5: 94.1, 7: 183.4, 9: 302.0, 10: 372.6, 11: 450.1, 12: 534.5}  # pinion torque [N m], 0.5 m arm
SPEEDS = [131.0, 262.0, 655.0, 1310.0, 2175.0, 3930.0, 5240.0]            # rpm: 0.5, 1, 2.5, 5, 8.3, 15, 20 m/s
ROUGHNESS = [0.1, 0.2, 0.3, 0.5, 0.8]                                       # Ra [um] of both flanks
LAWS = ["mesh_mean_friction", "mean_friction_iso", "mean_friction_iso_flash", "mean_friction_schlenk",
        "mean_friction_fernandes"]


def run(binary, tmp, sets):
    out = os.path.join(tmp, "r.h5")
    args = sum((["--set", s] for s in sets), [])
    subprocess.run([binary, "run", CASE, *args, "--positions", "101", "-q", "-o", out], check=True, cwd=ROOT,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with h5py.File(out) as f:
        attrs = f["lubrication"].attrs
        return {k: float(attrs[k]) for k in LAWS + ["min_lambda_smooth_film"]} | {
            "share": float(f["lubrication/asperity_load_share"][()].mean())}


def main(argv):
    binary = expected_table.binary_argument(argv, __doc__)
    if binary is None:
        return 2
    plot = argv[argv.index("--plot") + 1] if "--plot" in argv else None
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        oils = {name: run(binary, tmp, BASE + [f"torque={STAGES[9]}Nm", f"lubricant={path}"])
                for name, path in OILS.items()}
        load = {s: run(binary, tmp, BASE + [f"torque={t}Nm", f"lubricant={OILS['FVA 3 (mineral VG 100)']}"])
                for s, t in STAGES.items()}
        speed = {n: run(binary, tmp, [b for b in BASE if not b.startswith("speed")] +
                        [f"speed={n}rpm", f"torque={STAGES[9]}Nm", f"lubricant={OILS['FVA 3 (mineral VG 100)']}"])
                 for n in SPEEDS}
        rough = {ra: run(binary, tmp, [b for b in BASE if not b.startswith("ra")] +
                         [f"ra={ra}um", f"torque={STAGES[9]}Nm", f"lubricant={OILS['FVA 3 (mineral VG 100)']}"])
                 for ra in ROUGHNESS}
        slow = run(binary, tmp, ["ra=0.2um", "speed=131rpm", "oil_temperature=90degC", f"torque={STAGES[7]}Nm",
                                 f"lubricant={OILS['FVA 3 (mineral VG 100)']}"])
    for name, r in oils.items():
        for law in LAWS:
            rows.append({"key": name, "quantity": f"{law} [1]", "model": r[law], "reference": None,
                         "regression": "rel 1e-6"})
    mineral = oils["FVA 3 (mineral VG 100)"]["mesh_mean_friction"]
    rows.append({"key": "FVA 3 (mineral VG 100)", "quantity": "gear-mean friction against the FZG rig's mineral level [1]",
                 "model": mineral, "reference": 0.045, "tolerance": "30%", "verdict": "departs",
                 "regression": "rel 1e-6",
                 "reason": "DGMK (Doleschel et al.): mineral oil about 0.045 on the FZG rig (conditions not stated: 30 %); "
                           "the model is higher: the asperities carry most of the load at lambda 0.15-0.24 with the "
                           "assumed boundary coefficient 0.1 (README)"})
    ratio = oils["ESTR (ester VG 320)"]["mesh_mean_friction"] / oils["MINR (mineral VG 320)"]["mesh_mean_friction"]
    rows.append({"key": "ESTR / MINR", "quantity": "gear-mean friction ratio ester/mineral [1]", "model": ratio,
                 "reference": None, "regression": "rel 1e-6",
                 "reason": "DGMK (Doleschel et al.) measures esters at 0.6-1.0 of mineral on the FZG rig; not asserted: "
                           "with the same boundary coefficient for every oil the model's ratio is nearly the ratio of "
                           "the asperity shares and says little about the oil (README)"})
    rows.append({"key": "PAOR / MINR", "quantity": "gear-mean friction ratio PAO/mineral [1]",
                 "model": oils["PAOR (PAO VG 320)"]["mesh_mean_friction"] /
                 oils["MINR (mineral VG 320)"]["mesh_mean_friction"], "reference": None, "regression": "rel 1e-6",
                 "reason": "no measured ratio found (ISO's X_L gives 0.8)"})
    rows.append({"key": "FZG C_mod LS 7 0.5 m/s", "quantity": "gear-mean friction at the lowest speed [1]",
                 "model": slow["mesh_mean_friction"], "reference": 0.065, "tolerance": "15%", "verdict": "departs",
                 "regression": "rel 1e-6",
                 "reason": "Hinterstoisser 2014 (via Arana et al. 2019): about 0.065 at the lowest speed, boundary "
                           "along the path; the model's boundary limit is the assumed friction.mu 0.1"})
    mu = lambda d, key="mesh_mean_friction": [d[k][key] for k in sorted(d)]  # noqa: E731
    rises = lambda v: all(a < b for a, b in zip(v, v[1:]))  # noqa: E731
    falls = lambda v: all(a > b for a, b in zip(v, v[1:]))  # noqa: E731
    rows += [
        {"key": "trend", "quantity": "rises with load like ISO's mu_mC [bool]", "model": rises(mu(load)),
         "reference": True, "tolerance": "=", "verdict": "departs",
         "reason": "ISO/TS 6336-21's mu_mC rises as w^0.2 and FZG tests agree; in the Johnson-Greenwood-Poon "
                   "sharing the asperities' share falls with load below lambda ~1 (README)"},
        {"key": "trend", "quantity": "ISO mu_mC rises with load [bool]", "model": rises(mu(load, "mean_friction_iso")),
         "reference": True, "tolerance": "=", "verdict": "agrees", "reason": "w^0.2"},
        {"key": "trend", "quantity": "falls with speed like ISO's mu_mC [bool]", "model": falls(mu(speed)),
         "reference": True, "tolerance": "=", "verdict": "agrees",
         "reason": "the film thickens and takes the load; ISO's v^-0.2"},
        {"key": "trend", "quantity": "rises with roughness like ISO's mu_mC [bool]", "model": rises(mu(rough)),
         "reference": True, "tolerance": "=", "verdict": "agrees", "reason": "ISO's Ra^0.25; lambda falls"},
    ]
    for name, d, unit in (("load stage", load, ""), ("speed rpm", speed, ""), ("Ra um", rough, "")):
        for k, r in sorted(d.items()):
            rows.append({"key": f"{name} {k:g}", "quantity": "gear-mean friction [1]", "model": r["mesh_mean_friction"],
                         "reference": None, "regression": "rel 1e-6"})
    if plot:
        draw(plot, load, speed, rough)
    return expected_table.check(
        rows, os.path.join(HERE, "expected.csv"), argv, binary,
        "FZG C (Ra 0.3 um, 8.3 m/s, 90 degC, LS 9) gear-mean friction: four oils, load, speed and roughness sweeps",
        "validation/friction-fzg/check.py GEARTRIB --write")


def draw(path, load, speed, rough):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    labels = {"mesh_mean_friction": "geartrib (P/(P_in H_V))", "mean_friction_iso": "ISO/TS 6336-21/-22",
              "mean_friction_iso_flash": "ISO/TS 6336-20", "mean_friction_schlenk": "Schlenk",
              "mean_friction_fernandes": "Schlenk, Fernandes X_L"}
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), dpi=110, sharey=True)
    for ax, (d, x, xlabel) in zip(axes, ((load, sorted(load), "FZG load stage (0.5 m arm)"),
                                         (speed, [n * 0.0366 * 3.14159265 / 30 for n in sorted(speed)],
                                          "pitch-line speed [m/s]"),
                                         (rough, sorted(rough), "Ra of both flanks [um]"))):
        for k, law in enumerate(LAWS):
            ax.plot(x, [d[key][law] for key in sorted(d)], marker="o" if k == 0 else None,
                    linestyle="-" if k == 0 else "--", color=f"C{k}", label=labels[law])
        ax.axhline(0.045, color="0.4", linestyle=":", label="FZG rig, mineral (DGMK)")
        ax.set_xlabel(xlabel)
        ax.grid(True, alpha=0.3)
    axes[1].set_xscale("log")
    axes[0].set_ylabel("gear-mean friction [1]")
    axes[0].legend(fontsize=7)
    fig.suptitle("FZG C, FVA 3 at 90 degC (others as LS 9, 8.3 m/s, Ra 0.3 um)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
