"""Oracle rewards kept between benchmark runs (scripts/bench_agents.py, bench_zero_shot.py).

An oracle's grid search (coordinate descent with several UAVs) can cost minutes per scenario, and
comparing policies on one set asks for the same ones again. The cache is a JSON object of
rewards keyed by the scenario file's bytes, a kind (which oracle: the action space, or the
scenario's own settings) and the bytes of the build's Python binding and the rlpos libraries it
loads: a rebuilt reward model misses the cache.
"""
import glob
import hashlib
import json
import os
import subprocess


class OracleCacheError(Exception):
    """A cache file that cannot be used: the message names the file and what is wrong."""


def file_digest(path, digest):
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)


def binding_identity(build):
    """A digest of BUILD's Python binding and of the rlpos libraries it loads."""
    binding = glob.glob(os.path.join(build, "python", "rlpos", "_rlpos*.so"))
    if len(binding) != 1:
        raise OracleCacheError("no single Python binding in %s" % os.path.join(build, "python"))
    loaded = subprocess.run(["ldd", binding[0]], capture_output=True, text=True, check=True)
    libraries = sorted({line.split("=>")[1].split("(")[0].strip()
                        for line in loaded.stdout.splitlines()
                        if "librlpos" in line and "=>" in line})
    digest = hashlib.sha256()
    for path in binding + libraries:
        file_digest(path, digest)
    return digest.hexdigest()


def oracle_key(scenario, kind, identity):
    digest = hashlib.sha256()
    file_digest(scenario, digest)
    return "%s %s %s" % (digest.hexdigest(), kind, identity)


def load_cache(path):
    """The cached rewards ({} without a path or a file yet). Checked before any work: a bad path
    would otherwise surface only at the first save, after the first oracle's minutes."""
    if not path:
        return {}
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        raise OracleCacheError("--oracle-cache %s: folder %s does not exist" % (path, folder))
    if not os.path.exists(path):
        return {}
    try:
        with open(path) as f:
            cache = json.load(f)
    except OSError as e:
        raise OracleCacheError("--oracle-cache %s: %s" % (path, e.strerror))
    except ValueError as e:
        raise OracleCacheError("--oracle-cache %s: not JSON: %s" % (path, e))
    if not isinstance(cache, dict) or not all(isinstance(v, (int, float)) and
                                              not isinstance(v, bool) for v in cache.values()):
        raise OracleCacheError("--oracle-cache %s: not an object of rewards" % path)
    return cache


def save_cache(path, cache):
    """Written whole beside the file, then renamed: never a half-written cache."""
    partial = path + ".partial"
    with open(partial, "w") as f:
        json.dump(cache, f, indent=0, sort_keys=True)
    os.replace(partial, path)
