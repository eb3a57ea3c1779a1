#!/usr/bin/env bash
# `pip install .` from a clean copy of the tree into a fresh virtual environment (Debian's
# python3 with its system site packages, offline, no build isolation), then the package used
# from there: imported from the environment, not from the build tree, a scene simulated, every
# call documented.
# Usage: pip_install_test.sh SOURCE_DIR PYTHON
set -euo pipefail
source=$1
python=$2
work=$(mktemp -d /tmp/nineball-pip-XXXXXX)
trap 'rm -rf "$work"' EXIT
fail() {
  echo "pip install test: $*" >&2
  exit 1
}

# The tree as a clone would hold it: the files git tracks (all but build folders without git).
mkdir "$work/src"
if git -C "$source" rev-parse --git-dir >/dev/null 2>&1; then
  (cd "$source" && git ls-files -z --cached --others --exclude-standard |
    xargs -0 tar -cf - 2>/dev/null) | tar -xf - -C "$work/src"
else
  (cd "$source" && tar --exclude='./build*' -cf - .) | tar -xf - -C "$work/src"
fi

"$python" -m venv --system-site-packages "$work/venv" || fail "python3 -m venv failed"
# Unoptimised: what is checked is the packaging, not the physics' speed (a third of the build).
if ! NINEBALL_BUILD_TYPE=Debug "$work/venv/bin/pip" install --no-build-isolation --no-index --quiet "$work/src" \
  >"$work/pip.log" 2>&1; then
  tail -30 "$work/pip.log" >&2
  fail "pip install . failed"
fi

cd "$work"
# The package's files are those of python/nineball in the source, and the compiled core.
package_files=$(cd "$work/src/python/nineball" && ls | grep -v __pycache__ | sort | tr '\n' ' ')
out=$(PACKAGE_FILES="$package_files" "$work/venv/bin/python" - <<'PY'
import inspect, os, pydoc, sys
import nineball, nineball.env
assert nineball.__file__.startswith(sys.prefix), nineball.__file__
files = sorted(f for f in os.listdir(os.path.dirname(nineball.__file__)) if f != "__pycache__")
expected = sorted(os.environ["PACKAGE_FILES"].split())
assert [f for f in files if not f.startswith("_core.cpython")] == expected, (files, expected)
assert nineball.env.make("pot").step({"heading_deg": 0.0, "speed": 1.0})[2]
r = nineball.simulate({"balls": [{"id": 0, "x": 0, "y": 0}], "shot": {"heading_deg": 0, "speed": 1}})
for name in ("simulate", "simulate_many", "continue_from", "to_json"):
    assert inspect.signature(getattr(nineball, name)).parameters, name
    assert name in pydoc.render_doc(nineball), name
print(nineball.__version__, r["end"])
PY
) || fail "the installed package did not run"
[[ $out == "0.1.0 rest" ]] || fail "the installed package said: $out"
echo "pip install test: installed and ran ($out)"
