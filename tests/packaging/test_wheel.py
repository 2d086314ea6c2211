"""A wheel built from the checkout runs without it: installed into a fresh venv, with the project's dependencies
visible through PYTHONPATH (the main venv's site-packages, whose .pth files, so the editable install's hook, are not
processed there), from a folder outside the checkout, it translates its own packaged demo recipe and rolls out a
task of its packaged assets."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import sysconfig
import tomllib
import zipfile
from pathlib import Path

import pytest
from setuptools import find_packages

from cook2ltl import paths
from tests.models_required import require_models

ROOT = Path(__file__).resolve().parents[2]
DATA_PACKAGES = {"cook2ltl._assets", "cook2ltl._models"}  # assets/ and models/models.toml, mapped in pyproject.toml
NOT_SOURCES = shutil.ignore_patterns(".git", ".venv", "build", "dist", "*.egg-info", "__pycache__", ".pytest_cache",
                                     ".hypothesis")
TIMEOUT = 300  # seconds for any one step; the whole module takes about 30 s


def run(*command: str | Path, **options) -> subprocess.CompletedProcess:
    result = subprocess.run([str(part) for part in command], capture_output=True, text=True, timeout=TIMEOUT,
                            **options)
    assert result.returncode == 0, f"{' '.join(map(str, command))} exited {result.returncode}:\n" \
                                   f"{result.stdout[-3000:]}\n{result.stderr[-3000:]}"
    return result


@pytest.fixture(scope="module")
def wheel(tmp_path_factory) -> Path:
    """Built offline with the venv's setuptools, from a copy of the checkout, so the build leaves nothing in it."""
    scratch = tmp_path_factory.mktemp("build")
    source = scratch / "source"
    shutil.copytree(ROOT, source, symlinks=True, ignore=NOT_SOURCES)  # models/'s links to weights stay links
    run(sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "--no-index",
        "--disable-pip-version-check", "--quiet", "-w", scratch / "dist", source)
    (built,) = (scratch / "dist").glob("cook2ltl-*.whl")
    return built


@pytest.fixture(scope="module")
def installed(wheel, tmp_path_factory) -> dict:
    """A fresh venv holding only the wheel; the run's environment, its cwd and its own folders, all outside the
    checkout."""
    home = tmp_path_factory.mktemp("installed")
    venv = home / "venv"
    run(sys.executable, "-m", "venv", "--without-pip", venv)
    python = venv / "bin" / "python"
    run(sys.executable, "-m", "pip", "--python", python, "install", "--no-deps", "--no-index",
        "--disable-pip-version-check", "--quiet", wheel)
    env = {name: value for name, value in os.environ.items()
           if name not in {"PYTHONPATH", "COOK2LTL_ASSETS", "COOK2LTL_MODELS_DIR"}}
    dependencies = dict.fromkeys(sysconfig.get_paths()[kind] for kind in ("purelib", "platlib"))
    env.update(PYTHONPATH=os.pathsep.join(dependencies), COLUMNS="160", HF_HUB_OFFLINE="1", TRANSFORMERS_OFFLINE="1",
               COOK2LTL_MODEL_CACHE=str(paths.model_cache_dir()),  # weights only ever come from the per-user cache
               COOK2LTL_LIBRARY=str(home / "library.sqlite"), COOK2LTL_DATA=str(home / "data"),
               COOK2LTL_CONFIG=str(home / "config.toml"), COOK2LTL_KITCHEN_CACHE=str(home / "kitchen-cache"))
    work = home / "work"
    work.mkdir()
    return {"python": python, "venv": venv, "options": {"env": env, "cwd": work}}


def in_venv(installed: dict, *arguments: str | Path) -> subprocess.CompletedProcess:
    return run(installed["python"], *arguments, **installed["options"])


def test_every_package_under_app_is_in_the_packages_list_of_pyproject():
    configured = set(tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"])
    found = set(find_packages(ROOT / "app"))
    assert not found - configured, f"add {sorted(found - configured)} to [tool.setuptools] packages in pyproject.toml"
    assert configured - found == DATA_PACKAGES, "[tool.setuptools] packages names a package that is not in app/"


def test_the_wheel_carries_all_of_assets_and_of_models_only_the_manifest(wheel):
    with zipfile.ZipFile(wheel) as archive:
        names = set(archive.namelist())
        size = sum(info.file_size for info in archive.infolist())
    assets = {f"cook2ltl/_assets/{path.relative_to(ROOT / 'assets').as_posix()}"
              for path in (ROOT / "assets").rglob("*") if path.is_file() and "__pycache__" not in path.parts}
    assert assets and not assets - names
    assert {name for name in names if name.startswith("cook2ltl/_models/")} == {"cook2ltl/_models/models.toml"}
    assert size < 20_000_000, f"{size:,} bytes: something beyond code and assets is in the wheel"


def test_the_installed_package_is_the_wheel_s_and_reads_its_own_copies(installed):
    shown = in_venv(installed, "-c", "import json, cook2ltl; from cook2ltl import paths; print(json.dumps("
                    "[cook2ltl.__file__, str(paths.assets_dir()), str(paths.models_dir()), paths.IN_CHECKOUT]))")
    module, assets, models, in_checkout = json.loads(shown.stdout)
    package = Path(module).parent
    assert package.is_relative_to(installed["venv"]) and not Path(module).is_relative_to(ROOT)
    assert not in_checkout
    assert Path(assets) == package / "_assets" and (Path(assets) / "recipes" / "pasta-bake.txt").is_file()
    assert Path(models) == package / "_models" and [p.name for p in Path(models).iterdir()] == ["models.toml"]
    listed = in_venv(installed, "-m", "cook2ltl", "rollout", "--list")
    assert "chop-tomato" in listed.stdout


@pytest.fixture
def models():
    """The check every model-needing test makes (tests/models_required.py), before the wheel is built; here a
    missing model skips."""
    try:
        require_models("smollm2-135m", "gliner-cook2ltl", "spacy-sm")
    except pytest.fail.Exception as missing:
        pytest.skip(str(missing))


def test_the_installed_wheel_translates_its_demo_recipe_and_rolls_out_a_task(models, installed):
    package = Path(json.loads(in_venv(installed, "-c", "import json, cook2ltl; print(json.dumps(cook2ltl.__file__))"
                                      ).stdout)).parent
    recipe = package / "_assets" / "recipes" / "pasta-bake.txt"
    translated = json.loads(in_venv(installed, "-m", "cook2ltl", "translate", recipe, "--model", "smollm2-135m",
                                    "--json").stdout)
    assert translated["model"] == "smollm2-135m" and translated["primitives"] == "recipe"
    assert translated["formula"].startswith("F(") and len(translated["steps"]) >= 5
    rollout = in_venv(installed, "-m", "cook2ltl", "rollout", "chop-tomato", "--reference").stdout
    assert "verdict satisfied" in rollout and rollout.splitlines()[-1].startswith("success")


def test_the_installed_wheel_finds_the_provisioned_models_and_links_nothing_into_itself(models, installed):
    provisioned = in_venv(installed, "-m", "cook2ltl", "models", "provision", "smollm2-135m", "gliner-cook2ltl",
                          "spacy-sm")
    shown = provisioned.stdout + provisioned.stderr  # the progress goes to stderr
    assert shown.count("already provisioned") == 3, shown
    models = json.loads(in_venv(installed, "-c", "import json; from cook2ltl import paths; "
                                "print(json.dumps(str(paths.models_dir())))").stdout)
    assert [path.name for path in Path(models).iterdir()] == ["models.toml"]  # no links written into the venv
