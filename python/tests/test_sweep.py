"""geartrib.sweep on a Dask cluster against `geartrib sweep`: the same table, column for column,
to the last digit (the seconds column is each run's own wall time and is left out)."""

import numpy as np
import pytest

import geartrib as gt

distributed = pytest.importorskip("distributed")
pd = pytest.importorskip("pandas")

DEFAULT = "gears/m6z30.toml"
# Four points, one of which fails (x1 = 1.5 makes the wheel's tip interfere: the point's status
# and message, the sweep goes on), on a short path to keep the test quick.
AXES = {"x1": ["0", "1.5"], "torque": "500Nm:1000Nm:2", "positions": [21]}
SETS = ["--set", "x1=0,1.5", "--set", "torque=500Nm:1000Nm:2", "--set", "positions=21"]


@pytest.fixture(scope="module")
def client():
    """A local cluster of two single-threaded worker processes."""
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster, distributed.Client(cluster) as c:
        yield c


def assert_same_table(a, b):
    assert list(a.columns) == list(b.columns)
    assert a.attrs["units"] == b.attrs["units"]
    for name in a.columns:
        if name == "seconds":
            continue
        if a[name].dtype == object:
            assert list(a[name]) == list(b[name]), name
        else:  # NaN where the command has NaN (a failed point's summaries), else bit for bit
            assert np.array_equal(a[name].to_numpy(), b[name].to_numpy(), equal_nan=True), name


def test_dask_sweep_equals_the_command(tool, tmp_path, client):
    tool("sweep", DEFAULT, *SETS, "--threads", "2", "-q", "-o", tmp_path / "s.h5")
    command = gt.read_sweep(tmp_path / "s.h5")
    table = gt.sweep(gt.load_case(DEFAULT), AXES, client=client)
    assert len(table) == 4
    assert list(table["status"]) == ["ok", "ok", "error", "error"]
    assert "tip interference" in table["message"][2]
    assert_same_table(table, command)
    assert (table["seconds"] > 0).all()
    assert command.attrs["sweep"]["points_total"] == "4"
    # The lubricated runs' mesh-level values, one column each; NaN at the failed points.
    loss = table["mesh_power_loss_W"].to_numpy()
    assert (loss[:2] > 0).all() and np.isnan(loss[2:]).all()


def test_mixed_dry_and_lubricated_points(tool, tmp_path, client):
    """lubricant=none runs a point dry: no mesh-level values there (NaN), as in the command's table."""
    sets = ["--set", "lubricant=none,../lubricants/mineral-vg220.toml", "--set", "positions=21"]
    tool("sweep", DEFAULT, *sets, "--threads", "2", "-q", "-o", tmp_path / "d.h5")
    command = gt.read_sweep(tmp_path / "d.h5")
    table = gt.sweep(DEFAULT, {"lubricant": ["none", "../lubricants/mineral-vg220.toml"], "positions": [21]},
                     client=client)
    assert list(table["status"]) == ["ok", "ok"]
    assert np.isnan(table["tooth_friction_efficiency"][0]) and table["tooth_friction_efficiency"][1] < 1.0
    assert_same_table(table, command)


def test_failed_points_name_files_as_the_command_does(tool, tmp_path, client):
    """A point whose material file is missing: the same message as the command's, path and all."""
    sets = ["--set", "pinion.material=../materials/none.toml,../materials/steel-45.toml", "--set", "positions=11"]
    tool("sweep", DEFAULT, *sets, "--threads", "1", "-q", "-o", tmp_path / "m.h5")
    command = gt.read_sweep(tmp_path / "m.h5")
    table = gt.sweep(DEFAULT, {"pinion.material": ["../materials/none.toml", "../materials/steel-45.toml"],
                               "positions": [11]}, client=client)
    assert list(table["status"]) == ["error", "ok"]
    assert "gears/../materials/none.toml" in table["message"][0]
    assert_same_table(table, command)


def test_zipped_sweep_and_dict_result(client):
    table = gt.sweep(DEFAULT, {"torque": ["500Nm", "800Nm"], "positions": [21, 31]}, zip=True, client=client,
                     as_frame=False)
    assert list(table["point"]) == [0.0, 1.0]
    assert list(table["torque"]) == [500.0, 800.0] and table["units"]["torque"] == "N m"
    assert table["status"] == ["ok", "ok"]
    # The heavier point carries the higher Hertz pressure.
    assert table["hertz_p0_Pa_max"][1] > table["hertz_p0_Pa_max"][0]


def test_dict_case_sweeps_as_its_file(client):
    """A case given as a dict travels to the workers as text, its relative files taken from the
    folder given (the workers run in another working directory)."""
    import tomllib
    with open(DEFAULT, "rb") as f:
        tables = tomllib.load(f)
    axes = {"torque": ["700Nm"], "positions": [21]}
    from_dict = gt.sweep(gt.load_case(tables, directory="gears"), axes, client=client)
    from_file = gt.sweep(DEFAULT, axes, client=client)
    assert list(from_dict["status"]) == ["ok"]
    assert_same_table(from_dict, from_file)


def test_bad_axis_is_refused_before_any_point_runs(client):
    with pytest.raises(ValueError, match="module"):
        gt.sweep(DEFAULT, {"module": ["-4mm"]}, client=client)
    with pytest.raises(ValueError, match="no values"):
        gt.sweep(DEFAULT, {"module": []}, client=client)


def test_sweep_without_a_client_starts_a_local_cluster():
    table = gt.sweep(DEFAULT, {"positions": [11]})
    assert list(table["status"]) == ["ok"]
