"""Paths for the tests of the Python binding; ctest sets them (tests/worker/programs/python/CMakeLists.txt)."""
import os

import pytest

SOURCE = os.environ.get("RLPOS_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("RLPOS_BIN_DIR", os.path.join(SOURCE, "build", "bin"))


def closed_after(env):
    """The body of an env fixture: yields `env` to the test, closes it after."""
    yield env
    env.close()


def scenario_path(name):
    return os.path.join(SOURCE, "campaigns", "scenarios", name + ".json")


@pytest.fixture
def scenario_b():
    return scenario_path("b")
