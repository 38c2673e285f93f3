#!/usr/bin/python3
"""The mixed-EHL line-contact solver against its references (validation/mixed-ehl/README.md).

Usage: validation/mixed-ehl/check.py path/to/geartrib [--write]

Runs every case of the reference tables through the solver, turns each into rows (solver value,
reference, tolerance, verdict, reason) and checks them against expected.csv
(validation/expected_table.py; --write stores the solver's values). Exits 1 on any failure.

NOT WIRED YET: the solver has no command that runs one line-contact case. `run_case` below is the
one place that needs it; until then the script exits 2 after checking the reference tables. What
each case needs from the solver (inputs and outputs) is in RUNS and in the README.
"""
import csv
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.dont_write_bytecode = True
import expected_table  # noqa: E402

E_STAR = 206e9 / (2.0 * (1.0 - 0.3**2))  # the tables' steel

# What each kind of run gives the solver (LineEhlSolver: Fluid, E*, ContactInstant, EhlOptions, heights)
# and what it must return. Keys in SI; profiles on the solver's nodes.
RUNS = {
    "rigid": {
        "inputs": "Fluid{viscosity 0.01, pressure_viscosity 0, barus, compressible false, newtonian}, E* (table), "
                  "ContactInstant{line_load (rigid_isoviscous_case.csv), radius 0.01, speed1 = speed2 = 1}, "
                  "EhlOptions{inlet 960, outlet 120, nodes 1024/2048/4096}, heights 0; solve_steady",
        "outputs": "min_film, central_film, line_load, peak_pressure; grid x, pressure, state per node",
    },
    "smooth": {
        "inputs": "per smooth_line_reference.csv row: Fluid{viscosity_Pa_s, pressure_viscosity_per_Pa, barus or "
                  "roelands, compressible true/false}, composite_modulus_Pa, ContactInstant{line_load_N_per_m, radius_m, "
                  "speed1 = speed2 = entrainment_m_per_s}, EhlOptions{inlet 4 (6 where M < 15), outlet 1.5, nodes 1024/2048/4096}; "
                  "solve_steady",
        "outputs": "central_film, min_film, peak_pressure, line_load, load_error; grid x, pressure (for the spike "
                   "and the distance to Hertz)",
    },
    "waviness": {
        "inputs": "per roughness_attenuation.csv row: the smooth contact at (M, L) (W = 1.3e-4, G and U from M and L, "
                  "the smooth table's E*, R, eta0), pure rolling; heights r(x, t) = A_i cos(2 pi (x - u t)/lambda) on "
                  "one surface, A_i = amplitude_over_hc h_c(smooth), lambda = wavelength_over_b b; step() over a window "
                  "of >= 2 contact widths after the first crest reaches -b, dt <= lambda/(20 u)",
        "outputs": "the film at x = 0 over the last full period: A_d = (max - min)/2; the smooth h_c",
    },
    "limits": {
        "inputs": "a rough profile pair (the deterministic fidelity's generated ground flanks) at one position: "
                  "viscosity 1e-12 Pa s (dry limit); the smooth film 10x the roughness (thick film); "
                  "the speed swept over a decade (share vs speed)",
        "outputs": "pressure profile and contact_load (dry limit: against contact/half_plane_bem.hpp's "
                   "solve_load on the same gap, 1e-3 of p_H); asperity_share (0 in thick film; falling with speed)",
    },
}


def read_table(name):
    with open(os.path.join(HERE, name)) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def run_case(binary, kind, case):
    """The solver's outputs for one case (RUNS[kind]): a dict, or None while no command runs it."""
    return None


def rigid_rows(out, case, length):
    """Rows for the rigid case at one grid (out: the solver's outputs, case: rigid_isoviscous_case.csv)."""
    dx = (float(case["outlet_xi"]) - float(case["inlet_xi"])) * length / (out["nodes"] - 1)
    tol = 2.0 * dx / length
    return [{"key": f"rigid N {out['nodes']}", "quantity": "least film [m]", "model": out["min_film"],
             "reference": 10e-6, "tolerance": f"rel {tol:.3g}", "verdict": "agrees", "regression": "rel 1e-6",
             "reason": "twice the first-order upwind error measured by upwind_error_estimate.py (1.02 dx/sqrt(2Rh0))"},
            {"key": f"rigid N {out['nodes']}", "quantity": "rupture x [m]", "model": out["rupture_x"],
             "reference": float(case["exit_x_m"]), "tolerance": f"{2 * dx:.3g}", "verdict": "agrees",
             "regression": "rel 1e-6", "reason": "the last wet node within one node of x_e (measured); 2 dx"}]


def main(argv):
    binary = expected_table.binary_argument(argv, __doc__)
    if binary is None:
        return 2
    status = subprocess.run([sys.executable, os.path.join(HERE, "reference_tables.py")]).returncode
    if status:
        return status
    if run_case(binary, "rigid", read_table("rigid_isoviscous_case.csv")[0]) is None:
        print("the solver is not wired into check.py yet: what each run needs and returns:", file=sys.stderr)
        for kind, spec in RUNS.items():
            print(f"  {kind}: inputs {spec['inputs']}\n    outputs {spec['outputs']}", file=sys.stderr)
        return 2
    rows = []
    case = read_table("rigid_isoviscous_case.csv")[0]
    for nodes in (1024, 2048, 4096):
        out = run_case(binary, "rigid", dict(case, nodes=nodes))
        rows += rigid_rows(out, case, float(case["length_m"]))
    return expected_table.check(rows, os.path.join(HERE, "expected.csv"), argv, binary,
                                "the mixed-EHL line-contact solver against its references",
                                "validation/mixed-ehl/check.py GEARTRIB --write")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
