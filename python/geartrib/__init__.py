"""geartrib from Python: spur-gear mesh tribology along the line of action.

The same physics as the ``geartrib`` command, on NumPy arrays::

    import geartrib as gt
    case = gt.load_case()                       # gears/m6z30.toml, the default case
    res = gt.run(case.set(torque="2000 Nm"))    # xarray.Dataset over s_m (a dict without xarray)
    res.real_area_ratio.plot()
    table = gt.sweep(case, {"module": ["4mm", "6mm"], "rq": ["0.2um", "0.8um"]})   # on Dask

Values carry units as in a case file ("6 mm", "1000rpm"); everything returned is SI, each array
with its unit (``attrs["units"]`` of an xarray variable, ``units`` of a dict). Errors in a case
raise :class:`InputError` (a ValueError) with the command line's message, naming the file, line,
key, value and rule. The computation releases the GIL. docs/guide/python.md is the guide.
"""

from __future__ import annotations

import json
import math
import os
import re
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence

import numpy as np

from . import _geartrib as _core
from ._geartrib import InputError

__version__ = _core.__version__
__all__ = [
    "Case",
    "InputError",
    "load_case",
    "default_case_file",
    "run",
    "kinematics",
    "asperity",
    "asperity_models",
    "surface_statistics",
    "read_surface",
    "write_surface",
    "boundary_elements",
    "sweep",
    "read_sweep",
]


# -- cases ---------------------------------------------------------------------------------------

def _data_dirs() -> list[Path]:
    """Where gears/, materials/ and lubricants/ are: $GEARTRIB_DATA, beside an installed module
    (<prefix>/share/geartrib), the source tree of a build-tree module."""
    dirs = []
    if os.environ.get("GEARTRIB_DATA"):
        dirs.append(Path(os.environ["GEARTRIB_DATA"]))
    here = Path(__file__).resolve().parent
    for parent in here.parents:
        dirs.append(parent / "share" / "geartrib")
    source = getattr(_core, "source_dir", None)
    if source:
        dirs.append(Path(source))
    return dirs


def default_case_file() -> Path:
    """gears/m6z30.toml: in the working directory, else $GEARTRIB_DATA, an installed share/geartrib,
    or the source tree the module was built from (as the command line finds it)."""
    local = Path("gears/m6z30.toml")
    if local.exists():
        return local
    for d in _data_dirs():
        if (d / local).exists():
            return d / local
    raise FileNotFoundError("gears/m6z30.toml not found: set GEARTRIB_DATA to the folder holding gears/")


def _value_text(value: Any) -> str:
    """A value as typed after --set: strings as they are, numbers exactly (repr), booleans as TOML."""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        if not math.isfinite(value):
            raise ValueError(f"{value!r}: a case value must be finite")
        return repr(float(value))
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v, "an array item") for v in value) + "]"
    if value is None:
        raise ValueError("a case value cannot be None (leave the key out for its default)")
    return str(value)


def _toml_value(value: Any, where: str) -> str:
    """A value as TOML writes it: strings quoted and escaped (JSON's escapes are TOML's)."""
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, Mapping):
        raise ValueError(f"{where}: a table inside an array is not a case file's form")
    return _value_text(value)


def _toml_key(key: str) -> str:
    return key if _BARE_KEY.fullmatch(key) else json.dumps(key, ensure_ascii=False)


_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def _toml(table: Mapping[str, Any], prefix: str = "") -> str:
    """A nested dict as TOML text: a table's values first, then its sub-tables."""
    lines, tables = [], []
    for key, value in table.items():
        key = str(key)
        if isinstance(value, Mapping):
            tables.append((key, value))
        else:
            lines.append(f"{_toml_key(key)} = {_toml_value(value, key)}")
    out = "\n".join(lines) + ("\n" if lines else "")
    for key, value in tables:
        name = f"{prefix}.{_toml_key(key)}" if prefix else _toml_key(key)
        out += f"\n[{name}]\n" + _toml(value, name)
    return out


class Case:
    """A case: a case file (or a dict of its tables) and changes to its keys.

    Immutable: :meth:`set` returns a new case. Keys are the case file's dotted keys
    (``gear_pair.module``, ``pinion.flank.ra``) or the aliases of ``geartrib sweep --help``
    (``module``, ``torque``, ``rq``); values as a case file writes them (``"6 mm"``) or SI numbers.
    The case is loaded and checked when first used (:attr:`loaded`); a bad value raises
    :class:`InputError` naming the key and its ``--set``.
    """

    def __init__(self, file: str | os.PathLike | None = None, *, text: str | None = None,
                 name: str | None = None, changes: Sequence[tuple[str, str]] = ()):
        if text is None:
            self.file = str(file if file is not None else default_case_file())
            self.name = self.file
        else:
            self.file = ""
            self.name = str(name or "<dict>.toml")
        self.text = text
        # Relative file names (materials, lubricant, topography) are taken from here: the case
        # file's folder as given (messages name files as the command line does).
        self.directory = os.path.dirname(self.name)
        self.changes = tuple((str(k), str(v)) for k, v in changes)
        self._loaded = None

    @classmethod
    def from_dict(cls, tables: Mapping[str, Any], directory: str | os.PathLike = ".") -> "Case":
        """A case from a dict of the case file's tables ({"gear_pair": {"module": "6 mm", ...}, ...});
        relative file names (materials, lubricant, topography) are taken from `directory`."""
        case = cls(text=_toml(tables), name=os.path.join(str(directory), "<dict>.toml"))
        case.directory = str(directory)
        return case

    def set(self, changes: Mapping[str, Any] | None = None, **keys: Any) -> "Case":
        """A new case with these keys changed: ``case.set(torque="2000 Nm")`` or
        ``case.set({"pinion.flank.ra": "0.4 um"})``."""
        new = dict(changes or {})
        new.update(keys)
        merged = dict(self.changes)  # a key set again takes its new value, applied last
        for k, v in new.items():
            merged.pop(str(k), None)
            merged[str(k)] = _value_text(v)
        case = Case(self.file or None, text=self.text, name=self.name, changes=tuple(merged.items()))
        case.directory = self.directory
        return case

    @property
    def loaded(self):
        """The case as it runs (checked; warnings in .warnings, every key in .parameters)."""
        if self._loaded is None:
            self._loaded = _core.load_case(self.file, self.text, self.name, self.directory, list(self.changes))
        return self._loaded

    @property
    def parameters(self) -> dict[str, tuple[str, str]]:
        """Every key as it runs: key -> (value with its SI unit, origin: file:line, default or --set)."""
        return {k: (v, o) for k, v, o in self.loaded.parameters}

    @property
    def warnings(self) -> list[str]:
        return list(self.loaded.warnings)

    def __getstate__(self):  # pickled without the loaded case (a task's argument): loaded again there
        state = dict(self.__dict__)
        state["_loaded"] = None
        return state

    def __getitem__(self, key: str) -> str:
        return self.parameters[key][0]

    def __repr__(self) -> str:
        more = "".join(f", {k}={v}" for k, v in self.changes)
        return f"Case({self.name}{more})"

    def _portable(self) -> tuple[str, str, str, str, str]:
        """The case as another process or machine loads it: its text, the name it goes by in
        messages, the folder of its relative file names, and this process's working directory
        (which that folder is relative to; on a shared file system)."""
        text = self.text if self.text is not None else _core.read_case_text(self.file)
        return "", text, self.name, self.directory, os.getcwd()


def load_case(file: str | os.PathLike | Mapping[str, Any] | None = None, *, directory=".",
              **changes: Any) -> Case:
    """A case from a file (default: gears/m6z30.toml) or a dict of tables, with keys changed:
    ``load_case("gears/m6z30.toml", torque="2000 Nm")``. Loaded and checked at once."""
    case = Case.from_dict(file, directory) if isinstance(file, Mapping) else Case(file)
    if changes:
        case = case.set(changes)
    case.loaded  # errors here, not at the first run
    return case


def _as_case(case) -> Case:
    if case is None:
        return load_case()
    if isinstance(case, Case):
        return case
    return load_case(case)


# -- results -------------------------------------------------------------------------------------

def _xarray():
    try:
        import xarray
    except ImportError:
        return None
    return xarray


def _dataset(coordinate: str, series: Iterable[tuple[str, str, np.ndarray, str]], attrs: dict,
             as_dict: bool, variables: Sequence[tuple[str, str, tuple, np.ndarray, str]] = (),
             coords: Sequence[tuple[str, str, tuple, np.ndarray]] = ()):
    """Series as an xarray Dataset over `coordinate` (units in attrs), or a dict with "units".
    `variables` (name, unit, dims, values, group) and `coords` (name, unit, dims, values) over
    other dimensions join them (in a dict: arrays by name; a unit "" is none, as for text)."""
    series = list(series)
    xr = None if as_dict else _xarray()
    if xr is None:
        out = {name: values for name, _, values, _ in series}
        out.update({name: values for name, _, _, values in coords})
        out.update({name: values for name, _, _, values, _ in variables})
        out["units"] = {name: unit for name, unit, _, _ in series}
        out["units"].update({name: unit for name, unit, _, _ in coords if unit})
        out["units"].update({name: unit for name, unit, _, _, _ in variables})
        out["attrs"] = attrs
        return out
    coordinates = {name: values for name, _, values, _ in series if name == coordinate}
    data = {name: (coordinate, values, {"units": unit, "group": group})
            for name, unit, values, group in series if name != coordinate}
    data.update({name: (dims, values, {"units": unit, "group": group})
                 for name, unit, dims, values, group in variables})
    ds = xr.Dataset(
        data,
        coords={coordinate: (coordinate, coordinates[coordinate],
                             {"units": next(u for n, u, _, _ in series if n == coordinate)}),
                **{name: (dims, values, {"units": unit} if unit else {}) for name, unit, dims, values in coords}},
        attrs=attrs)
    return ds


# The result's per-position groups (geartrib run's /mesh, /contact, /contact/validity,
# /lubrication, /statistical, /mixed_ehl) and its parts over other dimensions.
_GROUPS = ("mesh", "contact", "validity", "lubrication", "statistical", "mixed_ehl")
_PARTS = _GROUPS + ("pressure_profiles", "running_in", "mixed_ehl_profiles", "mixed_ehl_summary")


def _mixed_ehl_parts(r: dict):
    """A mixed-EHL run's profiles through the contact as (name, unit, dims, values, group) variables
    and (name, unit, dims, values) coordinates: each kept position k on its own nodes
    ``mixed_ehl_x_m_<k>`` (its grid spans its own contact), ``mixed_ehl_<instant>_<quantity>_<k>``
    for the instants peak and middle; nothing for the other fidelities."""
    variables, coords = [], []
    units = {"pressure_Pa": "Pa", "film_m": "m", "shear_Pa": "Pa", "state": "1"}
    for p in r.get("mixed_ehl_profiles", []):
        k = p["position"]
        dim = f"mixed_ehl_x_m_{k}"
        coords.append((dim, "m", (dim,), p["x_m"]))
        for instant in ("peak", "middle"):
            for q, unit in units.items():
                variables.append((f"mixed_ehl_{instant}_{q}_{k}", unit, (dim,), p[f"{instant}_{q}"], "mixed_ehl"))
    return variables, coords


def _deterministic_parts(r: dict):
    """A deterministic run's pressure profiles and running-in as (name, unit, dims, values, group)
    variables and (name, unit, dims, values) coordinates, with the running-in's scalars (attrs);
    nothing for the statistical fidelities."""
    variables, coords, attrs = [], [], {}
    profiles = r.get("pressure_profiles", [])
    if profiles:
        x = profiles[0]["x_m"]
        if any(not np.array_equal(p["x_m"], x) for p in profiles):  # one strip grid for a run
            raise RuntimeError("the pressure profiles are on different strips")
        coords += [("position", "1", ("position",), np.array([p["position"] for p in profiles], dtype=np.int64)),
                   ("point", "", ("position",), np.array([p["point"] for p in profiles], dtype=str)),
                   ("position_s_m", "m", ("position",), np.array([p["s_m"] for p in profiles], dtype=float)),
                   ("x_m", "m", ("x_m",), x)]
        variables.append(("pressure_Pa", "Pa", ("position", "x_m"),
                          np.stack([p["pressure_Pa"] for p in profiles]), "pressure_profiles"))
    ri = r.get("running_in")
    if ri is not None:
        for name, unit, values in ri["history"]:
            if name == "mesh":  # the dimension: 0 = the new flanks, then each mesh run
                coords.append(("mesh", "1", ("mesh",), values.astype(np.int64)))
            else:
                variables.append((f"running_in_{name}", unit, ("mesh",), values, "running_in"))
        for gear in ("pinion", "wheel"):
            spacing = ri[f"{gear}_profile_spacing_m"]
            dim = f"running_in_{gear}_arc_m"  # along the active flank from its root end
            coords.append((dim, "m", (dim,), np.arange(ri[f"{gear}_profile_initial_m"].size) * spacing))
            for when in ("initial", "final"):
                variables.append((f"running_in_{gear}_profile_{when}_m", "m", (dim,), ri[f"{gear}_profile_{when}_m"],
                                  "running_in"))
        attrs = {k: v for k, v in ri.items() if k != "history" and not isinstance(v, np.ndarray)}
    return variables, coords, attrs


def run(case=None, *, positions: int | None = None, as_dict: bool = False):
    """The main job (``geartrib run``): the rough contact (and, lubricated, the film) at every
    position A -> E. An xarray Dataset with coordinate ``s_m`` (each variable's ``units`` and
    ``group``: mesh, contact, validity, lubrication, statistical; attrs: regime, verdict, warnings,
    path points), or, without xarray or with ``as_dict=True``, a dict of arrays with ``units`` and
    ``attrs``.

    A deterministic run (``contact.fidelity = "deterministic"``) adds the statistical model on the
    same flanks (``statistical_*`` over ``s_m``, group statistical); the pressure across the strip
    at the positions kept (``contact.pressure_profiles``) as ``pressure_Pa[position, x_m]``
    (``position``: index along the path, 0 at A, with coordinates ``point`` (A..E or "") and
    ``position_s_m``; ``x_m`` across the strip); and with ``running_in.meshes`` > 0 the running-in:
    ``running_in_*`` over ``mesh`` (0: the new flanks, NaN in the contact columns), the flanks'
    profiles ``running_in_{pinion,wheel}_profile_{initial,final}_m`` over
    ``running_in_{pinion,wheel}_arc_m`` (along the active flank from its root end) and attrs
    ``running_in.*`` (teeth, meshes, shakedown_mesh, tolerance_m, profile spacings). Flanks
    synthesised from a measured patch are recorded as attrs ``synthesis.<gear>.*`` (the file's
    ``/synthesis/<gear>``). A mixed-EHL run (``contact.fidelity = "mixed_ehl"``) adds its windows'
    series (group mixed_ehl, ``ehl_*`` over ``s_m``), the statistical model beside it, its summary
    as attrs ``mixed_ehl.*`` (the file's ``/mixed_ehl`` attributes) and the profiles through the
    contact kept as ``mixed_ehl_<peak|middle>_<pressure_Pa|film_m|shear_Pa|state>_<k>`` over
    ``mixed_ehl_x_m_<k>`` (k: the position's index). As a dict the same names hold the same arrays (``attrs["running_in"]``,
    ``attrs["synthesis"]`` dicts)."""
    case = _as_case(case)
    if positions is not None:
        case = case.set({"contact.positions": positions})
    r = _core.run(case.loaded)
    series = [(n, u, v, group) for group in _GROUPS for n, u, v in r.get(group, [])]
    variables, coords, running_in = _deterministic_parts(r)
    ehl_variables, ehl_coords = _mixed_ehl_parts(r)
    variables += ehl_variables
    coords += ehl_coords
    attrs = {k: v for k, v in r.items() if k not in _PARTS}
    if running_in:
        attrs["running_in"] = running_in
    if "mixed_ehl_summary" in r:
        attrs["mixed_ehl"] = r["mixed_ehl_summary"]
    attrs["case"] = repr(case)
    attrs["version"] = __version__
    if not (as_dict or _xarray() is None):  # netCDF-style attrs: flatten the nested ones
        flat = {}

        def flatten(prefix, v):
            if isinstance(v, dict):
                if "point" in v:  # the named points' table: one scalar per (quantity, point)
                    for kk, vv in v.items():
                        if kk != "point":
                            for point, x in zip(v["point"], vv):
                                flat[f"{prefix}.{kk}.{point}"] = x
                    return
                for kk, vv in v.items():
                    flatten(f"{prefix}.{kk}", vv)
            elif isinstance(v, list):
                flat[prefix] = "\n".join(str(x) for x in v)
            else:
                flat[prefix] = v

        for k, v in attrs.items():
            flatten(k, v)
        attrs = {k: int(v) if isinstance(v, bool) else v for k, v in flat.items()}  # netCDF has no bool
    return _dataset("s_m", series, attrs, as_dict, variables, coords)


def kinematics(case=None, points: str | Sequence[str] = "ABCDE", *, positions: int | None = None):
    """The pair along its line of action (``geartrib kinematics``) at named points (A..E; at B and D
    the single-tooth side of the jump) or at `positions` evenly spaced from A to E. A dict of
    arrays by column (names carry units: s_m, hertz_p0_Pa) with "point" the row labels."""
    case = _as_case(case)
    names = list(points) if isinstance(points, str) else list(points)
    header, labels, rows = _core.kinematics(case.loaded, names, positions)
    out = {"point": np.array(labels)}
    for j, name in enumerate(header):
        out[name] = rows[:, j].copy()
    return out


def asperity_models() -> list[str]:
    """The single-asperity models by name (the registry of ``geartrib asperity --model``)."""
    return list(_core.asperity_models())


def asperity(delta_star, model: str = "continuous", *, case=None, pair: Mapping[str, float] | None = None,
             stresses: bool = True, as_dict: bool = False):
    """One asperity law over an array of delta* = delta/delta_c (its own delta_c): load, area,
    contact radius, pressures, plastic fraction and (``stresses``) the largest von Mises stress and
    its depth, with the range flags. The pair (radius, modulus, youngs_modulus, poisson_ratio,
    yield_strength, hardness; SI) is the case's equivalent asperity unless `pair` is given.
    An xarray Dataset over delta_star (a dict without xarray); attrs: the critical values."""
    d = np.atleast_1d(np.asarray(delta_star, dtype=float))
    if d.ndim != 1:
        raise ValueError("delta_star must be a number or a 1-D array")
    loaded = None if pair is not None and case is None else _as_case(case).loaded
    columns, critical, pair_used, name, citation = _core.asperity(loaded, dict(pair) if pair is not None else None,
                                                                  model, d.ravel(), stresses)
    attrs = {"model": name, "citation": citation}
    attrs.update({f"critical_{k}": v for k, v in critical.items()})
    attrs.update({f"pair_{k}": v for k, v in pair_used.items()})
    series = [(n, u, v, "asperity") for n, u, v in columns]
    return _dataset("delta_star", series, attrs, as_dict)


def surface_statistics(z, dx: float, dy: float | None = None, *, form: int = 2, cutoff: float = 0.0,
                       outliers: float = 0.0) -> dict:
    """Statistics of a measured height grid z[y, x] in metres (NaN: missing) with spacing dx, dy
    [m], after the clean-up of ``geartrib surface stats`` (form polynomial of degree `form`,
    Gaussian waviness cut-off [m], outlier limit): Ra, Rq, Rsk, Rku, Rz, the lay, spectral moments,
    summits and McCool's estimates, named as that command names them (units in the name: Ra_m,
    lay_angle_deg, summit_density_1_per_m2); counts as floats."""
    z = np.ascontiguousarray(z, dtype=float)
    return _core.surface_statistics(z, float(dx), float(dy or 0.0), int(form), float(cutoff), float(outliers))


def read_surface(path: str | os.PathLike, *, unit: float = 1e-6, spacing: float = 0.0):
    """A topography file as ``geartrib surface`` reads it (by extension: .x3p, .h5, .xyz, .csv, ...;
    docs/guide/surface.md): ``(z, dx, dy)`` with z[y, x] in metres (NaN: missing) and the spacings
    [m]. `unit`: metres per length unit of ASCII files that do not state one; `spacing`: the grid
    spacing of grid files without one (file units). X3P and HDF5 files are in metres."""
    return _core.read_surface(str(path), float(unit), float(spacing))


def write_surface(path: str | os.PathLike, z, dx: float, dy: float | None = None, *, unit: float = 1e-6) -> None:
    """Writes a height grid z[y, x] [m] (NaN: missing) in the format of the extension, atomically:
    .x3p (ISO 25178-72, float64 heights in metres), .h5, or ASCII lengths in `unit` metres."""
    _core.write_surface(str(path), np.ascontiguousarray(z, dtype=float), float(dx), float(dy or 0.0), float(unit))


def boundary_elements(profile, dx: float, modulus: float, *, line_load: float | None = None,
                      approach: float | None = None, gap=None, pressure_cap: float = math.inf,
                      periodic: bool = False, reference_length: float | None = None,
                      tolerance: float = 1e-10) -> dict:
    """A rigid flat pressed on an elastic half-plane of plane-strain modulus `modulus` [Pa] (E/(1-nu^2))
    whose surface heights are `profile` [m] (spacing dx [m]), under a line load [N/m] or an approach
    [m] (of the flat, from touching the highest point), elastic-perfectly-plastic with `pressure_cap`
    [Pa]. Or give the undeformed `gap` [m] instead of the profile. Returns x, pressure, displacement
    and gap arrays with the solve's figures (keys carry units). The displacements' reference depth
    `reference_length` [m] (non-periodic) defaults as in ``geartrib multi-asperity``: at least
    20 um and twice the profile's length."""
    if gap is None:
        h = np.asarray(profile, dtype=float)
        gap = h.max() - h
    gap = np.ascontiguousarray(gap, dtype=float)
    if reference_length is None:
        reference_length = max(20e-6, 2.0 * gap.size * float(dx))
    return _core.boundary_elements(gap, float(dx), float(modulus), line_load, approach, float(pressure_cap),
                                   bool(periodic), float(reference_length), float(tolerance))


# -- sweeps --------------------------------------------------------------------------------------

def _axis_text(key: str, values) -> str:
    """An axis as `geartrib sweep --set` takes it: key=v1,v2 or key=lo:hi:n."""
    if isinstance(values, str):
        return f"{key}={values}"
    values = [_value_text(v) for v in values]
    if not values:
        raise ValueError(f"sweep axis {key!r} has no values")
    for v in values:  # the axis is parsed as the command line's: a comma or a range would split it
        if "," in v or (len(values) == 1 and v.count(":") == 2):
            raise ValueError(f"sweep axis {key!r}: value {v!r} cannot be swept (a ',' or 'lo:hi:n' in a value)")
    return f"{key}=" + ",".join(values)


def _run_point(source, base_changes, changes, index):
    """One point, on whichever worker runs it (the result is plain Python values). A worker in the
    submitting process's working directory names files as the command line does; elsewhere the
    relative folder is taken from that directory (messages then name it in full)."""
    file, text, name, directory, cwd = source
    if not os.path.isabs(directory) and os.path.realpath(os.getcwd()) != os.path.realpath(cwd):
        directory = os.path.join(cwd, directory)
    return _core.sweep_point(file, text, name, directory, base_changes, changes, index)


def _table(columns, as_frame: bool):
    if as_frame:
        try:
            import pandas as pd
        except ImportError:
            as_frame = False
    if not as_frame:
        out = {name: (np.asarray(values) if not text else list(values)) for name, _, text, values in columns}
        out["units"] = {name: unit for name, unit, _, _ in columns}
        return out
    frame = pd.DataFrame({name: (values if text else np.asarray(values)) for name, _, text, values in columns})
    frame.attrs["units"] = {name: unit for name, unit, _, _ in columns}
    return frame


def sweep(case, axes: Mapping[str, Any], *, zip: bool = False, client=None, as_frame: bool = True):
    """What-if sweep (``geartrib sweep``) with its points on a Dask cluster.

    `axes`: key -> values (a list, or "lo:hi:n" as on the command line), e.g.
    ``{"module": ["4mm", "6mm"], "rq": "0.2um:0.8um:4"}``; the points are the full factorial (the
    first key slowest) or, with ``zip=True``, the i-th value of each. `client`: a
    ``dask.distributed.Client`` (any cluster: LocalCluster, dask-jobqueue's SLURMCluster, ...);
    without one, a LocalCluster on this machine's cores for the sweep's duration.

    Returns the command's table, row for row and column for column (point, the swept values,
    status, message, seconds, contact ratio, plasticity index, regime, validity, positions per
    flag, a lubricated run's mesh-level values (NaN for a dry point), each quantity's
    _min/_mean/_max), as a pandas DataFrame with ``attrs["units"]`` (a dict
    of columns with "units" when ``as_frame=False`` or without pandas). A point that fails has
    status "error" and its message; the sweep goes on.
    """
    case = _as_case(case)
    axis_texts = [_axis_text(k, v) for k, v in axes.items()]
    points, _ = _core.sweep_plan(axis_texts, bool(zip))  # checked before any point runs
    case.loaded  # the base case must load: an error there is the user's, not a point's
    source = case._portable()
    base = list(case.changes)

    def gather(c):
        futures = c.map(_run_point, [source] * len(points), [base] * len(points), points, range(len(points)),
                        pure=False)
        return c.gather(futures)

    if client is None:
        from distributed import Client, LocalCluster
        with LocalCluster(n_workers=max(1, len(os.sched_getaffinity(0))), threads_per_worker=1,
                          processes=True, dashboard_address=":0") as cluster, Client(cluster) as c:
            results = gather(c)
    else:
        results = gather(client)
    return _table(_core.sweep_table(axis_texts, bool(zip), list(results)), as_frame)


def read_sweep(path: str | os.PathLike, *, as_frame: bool = True):
    """A ``geartrib sweep`` HDF5 file as the table :func:`sweep` returns (attrs: the /sweep
    attributes and the scene)."""
    columns, attributes, scene = _core.read_sweep(str(path))
    table = _table(columns, as_frame)
    if hasattr(table, "attrs"):
        table.attrs.update({"sweep": dict(attributes), "scene": scene})
    return table
