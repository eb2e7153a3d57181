"""The `sdt` command: JSON listings, help texts, and user errors without tracebacks."""

from __future__ import annotations

import json

import pytest
import typer
from typer.testing import CliRunner

from sdt_framework.cli.main import app

from ..helpers import run_sdt

runner = CliRunner()


def json_of(*args: str) -> list | dict:
    result = runner.invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_sensors_list_json_has_table1_profiles():
    sensors = {s["name"]: s for s in json_of("sensors", "list")}
    assert {"wilcoxon-786b10", "adxl345", "adxl357"} <= set(sensors)
    assert sensors["adxl345"]["sampling_rate_hz"] == 3200
    assert sensors["adxl345"]["noise_density_ug_rthz"] == 290
    assert sensors["adxl357"]["digital_order"] == 8
    assert sensors["adxl357"]["digital_cutoff_hz"] == 1000
    assert sensors["wilcoxon-786b10"]["full_scale_g"] == 80
    assert sensors["wilcoxon-786b10"]["inject_noise"] is False


def test_classifiers_list_json_has_table3_hyperparameters():
    clfs = {c["name"]: c for c in json_of("classifiers", "list")}
    assert {"lr", "knn", "rf", "xgb", "mlp"} <= set(clfs)
    assert clfs["lr"]["params"] == {"max_iter": 2000, "class_weight": "balanced"}
    assert clfs["knn"]["params"] == {"n_neighbors": 5, "weights": "distance"}
    assert clfs["xgb"]["params"] == {"n_estimators": 100, "learning_rate": 0.1, "max_depth": 5}
    assert clfs["mlp"]["params"]["hidden_layer_sizes"] == [256, 128, 64]
    assert clfs["mlp"]["params"]["alpha"] == 0.005


def test_features_list_json_has_paper8_with_32_bytes():
    sets = {s["name"]: s for s in json_of("features", "list")}
    assert sets["paper8"]["feature_names"] == [
        "sigma",
        "S",
        "K",
        "CF",
        "A_RMS",
        "A_Peak",
        "V_RMS",
        "D_RMS",
    ]
    assert sets["paper8"]["bytes_per_window_per_axis"] == 32
    assert sets["paper8"]["bytes_per_window_triaxial"] == 96


def test_plugins_list_json_shows_distribution_version_status():
    plugins = {p["name"]: p for p in json_of("plugins", "list")}
    assert plugins["adxl345"]["distribution"] == "sdt-framework"
    assert plugins["adxl345"]["status"] == "loaded"
    assert plugins["adxl345"]["provides"] == {"sensor": ["adxl345"]}
    assert plugins["adxl345"]["version"]


def test_sensors_show_table():
    result = runner.invoke(app, ["sensors", "show", "adxl357"])
    assert result.exit_code == 0
    assert "noise_density_ug_rthz" in result.stdout and "0.00390625" not in result.stdout


def test_sensors_show_prints_tolerances_and_stages_readably(tmp_path):
    """adxl345's Rev. G tolerances are shown (they are not hashed, so not in content_dict)."""
    result = runner.invoke(app, ["sensors", "show", "adxl345", "--json"])
    data = json.loads(result.stdout)
    assert data["tolerances"]["scale.error_pct"] == {"distribution": "uniform", "spread": 10.2}
    profile = tmp_path / "gm.toml"
    profile.write_text(
        'name = "gm"\nsampling_rate_hz = 3200\nfull_scale_g = 16\nadc_bits = 13\n'
        "noise_density_ug_rthz = 290\nmech_cutoff_hz = 5500\nanalog_cutoff_hz = 1600\n"
        'stages = [{name = "gauss-markov", params = {sigma_ug = 200, tau_s = 2}}]\n'
    )
    args = ["--sensor-file", str(profile), "sensors", "show", "gm"]
    result = runner.invoke(app, args, env={"COLUMNS": "250"})
    assert "gauss-markov(sigma_ug=200.0, tau_s=2.0)" in result.stdout


def test_unknown_sensor_is_one_line_without_traceback():
    result = run_sdt("sensors", "show", "adxl35")
    assert result.returncode == 2
    assert "Traceback" not in result.stderr
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    joined = " ".join(lines)
    assert joined.startswith("error: unknown sensor 'adxl35'")
    assert "Did you mean" in joined


def test_help_of_plugins_list_documents_the_switches():
    out = runner.invoke(app, ["plugins", "list", "--help"], env={"COLUMNS": "200"}).stdout
    for switch in ("SDT_PLUGINS", "SDT_BLOCK_PLUGINS", "SDT_TRACE_HOOKS"):
        assert switch in out


def leaf_commands(group, prefix: tuple[str, ...] = ()):
    for name, command in group.commands.items():
        if hasattr(command, "commands"):  # a group (typer vendors its own click)
            yield from leaf_commands(command, (*prefix, name))
        else:
            yield (*prefix, name)


@pytest.mark.parametrize("path", sorted(leaf_commands(typer.main.get_command(app))), ids=" ".join)
def test_every_command_has_help_with_an_example(path):
    result = runner.invoke(app, [*path, "--help"], env={"COLUMNS": "200"})
    assert result.exit_code == 0
    assert "Example" in result.stdout, f"`sdt {' '.join(path)} --help` shows no example"


def test_a_process_builds_the_command_once_and_each_run_parses_afresh(monkeypatch):
    """``main()`` reuses the click command Typer built (not ``app()``, which builds it at
    every call); a run's options never leak into the next one."""
    import typer.main

    from sdt_framework.cli import main as cli

    from ..helpers import sdt_here

    built = []
    real = typer.main.get_command
    monkeypatch.setattr(typer.main, "get_command", lambda app: built.append(app) or real(app))
    cli.command.cache_clear()
    try:
        cheap = sdt_here("sensors", "list", "--max-price", "15EUR")
        everything = sdt_here("sensors", "list")
        again = sdt_here("sensors", "list", "--max-price", "15EUR")
    finally:
        cli.command.cache_clear()
    assert built == [app]
    assert cheap.returncode == everything.returncode == again.returncode == 0
    assert cheap.stdout == again.stdout
    assert len(everything.stdout.splitlines()) > len(cheap.stdout.splitlines())
