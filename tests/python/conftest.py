"""Fixtures of the Python module's tests: the repository, the `pound` program to compare with."""

import os
import pathlib
import shutil

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture
def repository():
    return REPOSITORY


@pytest.fixture
def models():
    return REPOSITORY / "models"


@pytest.fixture
def pound_program():
    """The `pound` program of the same build (ctest sets POUND_PROGRAM)."""
    program = os.environ.get("POUND_PROGRAM") or shutil.which("pound")
    if not program:
        pytest.skip("POUND_PROGRAM is not set and no pound on PATH: nothing to compare with")
    return program


@pytest.fixture
def shared_records():
    folder = REPOSITORY.parent / "shared" / "ground_motions"
    if not folder.is_dir():
        pytest.skip("../shared/ground_motions is absent (a clone on its own)")
    return folder
