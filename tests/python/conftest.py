"""Shared fixtures of the Python tests: the shared corpus beside the project (as
tests/support/shared_corpus.h finds it) and the contain command of the same build."""

import json
import os
import pathlib

import pytest

PROJECT = pathlib.Path(__file__).resolve().parents[2]


def shared_dir():
    """../shared beside the project (it holds corpus/), or None in a user's clone."""
    shared = PROJECT.parent / "shared"
    return shared if (shared / "corpus").is_dir() else None


@pytest.fixture
def shared():
    path = shared_dir()
    if path is None:
        pytest.skip("../shared is absent (a user's clone): corpus test skipped")
    return path


@pytest.fixture
def cli():
    """The contain command built beside the module (CONTAIN_CLI, set by CTest)."""
    path = os.environ.get("CONTAIN_CLI", "")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("the contain command is not built in this tree (CONTAIN_CLI unset)")
    return path


def read_jsonl(path):
    with open(path) as lines:
        return [json.loads(line) for line in lines if line.strip()]


@pytest.fixture(scope="module")
def client():
    """A distributed.LocalCluster of two one-thread worker processes on loopback."""
    distributed = pytest.importorskip("distributed")
    cluster = distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                       host="127.0.0.1", dashboard_address=None)
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()
