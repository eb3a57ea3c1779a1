"""nineball.plot: each picture drawn, saved and looked into (the path's colours are there),
and bad arguments refused by name."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

import matplotlib.image  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

import nineball  # noqa: E402
from nineball import plot  # noqa: E402

SOURCE = os.environ.get("NINEBALL_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def draw_scene(trace=None):
    with open(os.path.join(SOURCE, "docs", "draw-shot.json")) as f:
        scene = json.load(f)
    if trace is not None:
        scene["trace"] = trace
    return scene


def pixels_of(png, colour, tolerance=0.06):
    """How many pixels of the PNG are ``colour`` ("#rrggbb")."""
    image = matplotlib.image.imread(str(png))[:, :, :3]
    rgb = np.array([int(colour[i:i + 2], 16) / 255 for i in (1, 3, 5)])
    return int(np.sum(np.all(np.abs(image - rgb) < tolerance, axis=2)))


def saved(ax, path):
    ax.figure.savefig(str(path), dpi=80)
    plt.close(ax.figure)
    return path


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def test_import_nineball_imports_no_matplotlib():
    code = "import sys, nineball, nineball.plot, nineball.types; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "False"


def test_table_draws_the_cloth_and_pockets(tmp_path):
    png = saved(plot.table(), tmp_path / "table.png")
    assert pixels_of(png, "#2e8b57") > 10000   # the cloth (colours.hpp's kCloth)
    assert pixels_of(png, "#0c0c0c") > 200     # the pockets
    carom = saved(plot.table(table="carom", physics={"preset": "carom"}), tmp_path / "c.png")
    assert pixels_of(carom, "#0c0c0c") == 0    # no pockets on a carom table


def test_shot_draws_paths_by_phase_and_events(tmp_path):
    scene = draw_scene({"hz": 1})
    r = nineball.simulate(scene)
    ax = plot.shot(r, scene=scene)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert {"sliding", "rolling", "ball contact", "pocketed"} <= set(labels)
    png = saved(ax, tmp_path / "shot.png")
    # The sliding path's orange: absent from the table alone, so the check can fail.
    assert pixels_of(png, plot.PHASE_COLOURS["sliding"]) > 50
    bare = saved(plot.table(), tmp_path / "bare.png")
    assert pixels_of(bare, plot.PHASE_COLOURS["sliding"]) == 0


def test_shot_of_a_result_read_back_from_json(tmp_path):
    scene = draw_scene({"hz": 50})
    plain = json.loads(nineball.to_json(nineball.simulate(scene)))
    png = saved(plot.shot(plain, scene=scene, events=False), tmp_path / "plain.png")
    assert pixels_of(png, plot.PHASE_COLOURS["rolling"]) > 50
    assert pixels_of(saved(plot.shot(plain), tmp_path / "alone.png"),
                     plot.PHASE_COLOURS["rolling"]) > 50


def test_shot_without_a_trace_draws_the_balls_and_says_so(tmp_path):
    scene = draw_scene()
    ax = plot.shot(nineball.simulate(scene), scene=scene)
    assert "no trace" in ax.get_title()
    png = saved(ax, tmp_path / "still.png")
    assert pixels_of(png, plot.ball_colour(9)[0]) > 5     # the 9 where it stopped
    assert pixels_of(png, plot.PHASE_COLOURS["sliding"]) == 0


def test_ball_colours_are_the_games():
    assert plot.ball_colour(1) == ("#fac410", False)
    assert plot.ball_colour(9) == ("#fac410", True)
    assert plot.ball_colour(8)[0] == "#121212"
    assert plot.ball_colour(2, "carom")[0] == "#ce1a20"
    assert plot.ball_colour(21, "snooker")[0] == "#121212"


def test_fit_overlays_the_fitted_run_on_the_recording(tmp_path):
    scene = {"table": "carom", "physics": {"preset": "carom"},
             "balls": [{"id": 0, "x": -0.6, "y": -0.25}, {"id": 1, "x": -0.15, "y": -0.1},
                       {"id": 2, "x": 0.9, "y": 0.45}],
             "shot": {"heading_deg": 19.0, "speed": 3.0, "tip": [0.2, 0.1]}}
    recording = nineball.record(scene, ["white", "yellow", "red"], hz=25)
    answer = nineball.fit(recording, evals=300)[0]
    ax = plot.fit(answer, recording)
    assert "RMSE" in ax.get_title()
    png = saved(ax, tmp_path / "fit.png")
    assert pixels_of(png, "#f6c828") > 30   # the yellow's dots and line


def test_animate_saves_a_gif_and_a_page(tmp_path):
    scene = draw_scene({"hz": 20})
    r = nineball.simulate(scene)
    anim = plot.animate(r, str(tmp_path / "shot.gif"), fps=4, scene=scene)
    from PIL import Image

    with Image.open(tmp_path / "shot.gif") as gif:
        assert gif.n_frames >= int(r["time"] * 4)
        gif.seek(gif.n_frames - 1)
        last = np.asarray(gif.convert("RGB"))
    assert last.std() > 10   # a picture, not a blank frame
    plot.animate(r, str(tmp_path / "shot.html"), fps=2)
    page = (tmp_path / "shot.html").read_text()
    assert "<script" in page and "Animation" in page
    assert "<script" in anim._repr_html_()   # what a notebook shows


def test_bad_arguments_are_refused_by_name(tmp_path):
    r = nineball.simulate(draw_scene())
    with pytest.raises(TypeError, match="result: expected a result"):
        plot.shot({"time": 1.0})
    with pytest.raises(TypeError, match="result: expected a result"):
        plot.shot("a result")
    with pytest.raises(TypeError, match="scene: expected the scene"):
        plot.shot(r, scene=[1, 2])
    with pytest.raises(TypeError, match="table: expected"):
        plot.table(table=9)
    with pytest.raises(ValueError, match="table"):
        plot.table(table="10ft")
    with pytest.raises(ValueError, match="result: has no trace"):
        plot.animate(r)
    traced = nineball.simulate(draw_scene({"hz": 10}))
    with pytest.raises(ValueError, match="path: expected a file name ending in .gif or .html"):
        plot.animate(traced, str(tmp_path / "shot.mp4"))
    with pytest.raises(ValueError, match="fps"):
        plot.animate(traced, fps=0)
    with pytest.raises(ValueError, match="refused"):
        plot.fit({"id": 3, "error": "balls.red.t: decreasing at sample 5"}, {"balls": {}})
    with pytest.raises(TypeError, match="answer: expected one answer"):
        plot.fit(r, {"balls": {}})
    with pytest.raises(TypeError, match="recording: expected"):
        plot.fit({"scene": draw_scene(), "names": {"0": "0"}, "strike_time": 0.0}, [1])
