"""The Python module (tools/python): reading, arrays in and out, fit, sample, measure, edit, write.
Run by ctest as Python.Pytest, with the module's build directory on PYTHONPATH and the project's
data directory in SHAPEPROC_DATA_DIR."""
import json
import math
import os

import numpy as np
import pytest

import shapeproc

DATA = os.environ.get("SHAPEPROC_DATA_DIR",
                      os.path.join(os.path.dirname(__file__), "..", "..", "data"))
DOTS = os.path.join(DATA, "svg", "dots-random.svg")


@pytest.fixture(scope="module")
def dots():
    return shapeproc.read(DOTS)


@pytest.fixture(scope="module")
def dots_model(dots):
    return shapeproc.fit(dots, estimator="mpl")


def test_read_gives_arrays(dots):
    assert dots.dimension == 2
    assert dots.positions.shape == (len(dots), 2)
    assert dots.categories.shape == (len(dots),)
    lower, upper = dots.window
    assert np.all(dots.positions >= lower) and np.all(dots.positions <= upper)
    assert len(dots) == 30


def test_points_from_arrays_round_trip():
    positions = np.array([[1.0, 2.0], [3.0, 4.0], [5.0, 1.0]])
    scene = shapeproc.points(positions, categories=np.array([0, 1, 1], dtype=np.int32),
                             window=[0, 10, 0, 5], radii=np.array([0.5, 0.5, 1.0]),
                             category_names=["a", "b"])
    assert np.array_equal(scene.positions, positions)
    assert list(scene.categories) == [0, 1, 1]
    assert scene.category_names == ["a", "b"]
    assert np.array_equal(scene.window, [[0, 0], [10, 5]])


@pytest.mark.parametrize("kwargs, message", [
    (dict(categories=np.array([0, 1], dtype=np.int32)), "categories"),
    (dict(window=[0, 2, 0, 2]), "outside the window"),
    (dict(radii=np.array([1.0, -1.0, 1.0])), "radius"),
])
def test_points_refuses_bad_arrays(kwargs, message):
    positions = np.array([[1.0, 1.0], [3.0, 4.0], [5.0, 1.0]])
    kwargs.setdefault("window", [0, 10, 0, 10])
    with pytest.raises(ValueError, match=message):
        shapeproc.points(positions, **kwargs)


def test_measure_counts_exactly(dots):
    m = shapeproc.measure(dots)
    lower, upper = dots.window
    area = float(np.prod(upper - lower))
    assert m["counts"] == [30]
    assert m["intensity"][0] == pytest.approx(30 / area, rel=1e-12)
    assert len(m["nearest"]) > 0 and m["mean_nearest"] > 0


def test_fit_sample_density_and_seed(dots, dots_model):
    lower, upper = dots.window
    size = list(2 * (upper - lower))
    first = shapeproc.sample(dots_model, size, seed=1)
    again = shapeproc.sample(dots_model, size, seed=1)
    other = shapeproc.sample(dots_model, size, seed=2)
    assert np.array_equal(first.positions, again.positions)
    assert not np.array_equal(first.positions, other.positions)
    # Four windows' worth: within 4 Poisson standard errors of 120 (the fit checks its density on
    # this very torus; a regular pattern varies less than Poisson).
    for out in (first, other):
        assert abs(len(out) - 120) <= 4 * math.sqrt(120)
    assert dots_model.path == "pseudo-likelihood"


def test_edit_scales_beta_exactly(dots_model, tmp_path):
    path = tmp_path / "model.json"
    dots_model.save(str(path))
    edited = shapeproc.load_model(str(path))
    edited.scale_beta(0.5)
    assert np.allclose(edited.beta, 0.5 * dots_model.beta, rtol=1e-12)
    edited.set_beta(0, 0.01)
    assert edited.beta[0] == 0.01
    with pytest.raises(ValueError):
        edited.scale_beta(-1.0)


def test_write_read_and_model_round_trip(tmp_path, dots, dots_model):
    lower, upper = dots.window
    out = shapeproc.sample(dots_model, list(2 * (upper - lower)), seed=3)
    svg = tmp_path / "out.svg"
    shapeproc.write(out, str(svg))
    back = shapeproc.read(str(svg))
    assert len(back) == len(out)
    assert np.allclose(np.sort(back.positions, axis=0), np.sort(out.positions, axis=0), atol=1e-3)
    assert "seed 3" in svg.read_text()
    path = tmp_path / "model.json"
    dots_model.save(str(path))
    loaded = shapeproc.load_model(str(path))
    assert np.array_equal(loaded.beta, dots_model.beta)
    assert loaded.categories == dots_model.categories
    assert json.loads(loaded.to_json())["interaction"] == json.loads(dots_model.to_json())["interaction"]


def test_sample_is_the_commands_output(dots_model, tmp_path):
    """The same model, size and seed give `shapeproc sample`'s output, element for element."""
    command = os.environ.get("SHAPEPROC")
    if not command:
        pytest.skip("SHAPEPROC (the command) is not set")
    import subprocess
    model = tmp_path / "model.json"
    dots_model.save(str(model))
    out = tmp_path / "out.csv"
    subprocess.run([command, "sample", str(model), "--size", "300,300", "--seed", "5", "-o",
                    str(out), "--quiet"], check=True, capture_output=True)
    made = shapeproc.sample(dots_model, [300, 300], seed=5)
    rows = np.loadtxt(out, delimiter=",", skiprows=1, usecols=(0, 1), ndmin=2)
    assert rows.shape == made.positions.shape
    assert np.allclose(rows, made.positions, atol=1e-6)


def test_fit_of_a_tile_is_periodic():
    """A seamless tile is fitted on its torus, as `shapeproc fit --tile` fits it."""
    tile = shapeproc.read(os.path.join(DATA, "third-party", "hero-patterns", "bubbles.svg"),
                          tile=True)
    model = shapeproc.fit(tile, estimator="mpl", tile=True)
    assert json.loads(model.to_json())["fit"]["edge"] == "periodic"


def test_compare_writes_every_method_and_the_page(tmp_path):
    runs = shapeproc.compare(DOTS, "2W,2H", str(tmp_path / "page"), methods="tile,davison", seed=2)
    assert [r["method"] for r in runs] == ["tile", "davison"]
    for r in runs:
        assert r["failure"] == ""
        assert os.path.exists(r["output"]) and r["elements"] > 0
    assert os.path.exists(runs[0]["index"])
    with pytest.raises(RuntimeError, match="methods"):
        shapeproc.compare(DOTS, "2W,2H", str(tmp_path / "bad"), methods="tile,magic")
