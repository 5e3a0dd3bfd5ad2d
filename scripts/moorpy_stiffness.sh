#!/usr/bin/env bash
# MoorPy's 6x6 mooring stiffness of OC3 (the reference of hawser's body_stiffness test), in a
# throwaway virtual environment with PyPI's moorpy.
#
# Usage: scripts/moorpy_stiffness.sh [moorpy_stiffness.py options...]
#
# Environment:
#   MOORPY_VENV      virtualenv path (default <repo>/.venv-moorpy, gitignored)
#   MOORPY_VERSION   moorpy version (default 1.3.0)
#   PYTHON           interpreter used to create the venv (default python3)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="${MOORPY_VENV:-$ROOT/.venv-moorpy}"
MOORPY_VERSION="${MOORPY_VERSION:-1.3.0}"
if [ ! -x "$VENV/bin/python" ]; then
    echo "creating throwaway virtualenv $VENV" >&2
    "${PYTHON:-python3}" -m venv "$VENV"
fi
if ! "$VENV/bin/python" -c "
import sys
from importlib.metadata import version
sys.exit(0 if version('moorpy') == '$MOORPY_VERSION' else 1)
" 2>/dev/null; then
    echo "installing moorpy==$MOORPY_VERSION into $VENV" >&2
    "$VENV/bin/python" -m pip install --quiet --disable-pip-version-check \
        "moorpy==$MOORPY_VERSION" >&2
fi
exec "$VENV/bin/python" "$ROOT/scripts/moorpy_stiffness.py" "$@"
