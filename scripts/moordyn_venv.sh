# Sourced by scripts/bench.sh and scripts/moordyn_compare.sh: a throwaway virtual environment
# with MoorDyn from PyPI. Sets VENV and MOORDYN_VERSION; needs ROOT.
#   BENCH_VENV       virtualenv path (default <repo>/.venv-bench, gitignored)
#   MOORDYN_VERSION  moordyn version (default 2.7.2)
#   PYTHON           interpreter used to create the venv (default python3)
VENV="${BENCH_VENV:-$ROOT/.venv-bench}"
MOORDYN_VERSION="${MOORDYN_VERSION:-2.7.2}"
if [ ! -x "$VENV/bin/python" ]; then
    echo "creating throwaway virtualenv $VENV" >&2
    "${PYTHON:-python3}" -m venv "$VENV"
fi
if ! "$VENV/bin/python" -c "
import sys
from importlib.metadata import version
sys.exit(0 if version('moordyn') == '$MOORDYN_VERSION' else 1)
" 2>/dev/null; then
    echo "installing moordyn==$MOORDYN_VERSION into $VENV" >&2
    "$VENV/bin/python" -m pip install --quiet --disable-pip-version-check \
        "moordyn==$MOORDYN_VERSION" >&2
fi
