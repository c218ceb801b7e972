import os
import pathlib
import shutil

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
LOGS = REPO / "tests" / "data" / "tenhou"


@pytest.fixture(scope="session")
def cli():
    """The `rinshan` command built by cargo: the Rust side the package is checked against."""
    for p in (
        os.environ.get("RINSHAN_CLI"),
        REPO / "target" / "release" / "rinshan",
        REPO / "target" / "debug" / "rinshan",
        shutil.which("rinshan"),
    ):
        if p and pathlib.Path(p).is_file():
            return str(p)
    pytest.fail("build the CLI first (cargo build) or set RINSHAN_CLI")


@pytest.fixture(scope="session")
def log_path():
    return str(sorted(LOGS.glob("*.json"))[0])
