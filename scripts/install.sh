#!/usr/bin/env bash
# Install packages into the project's virtual environment, creating it when missing (what `make` runs).
#   usage: scripts/install.sh PIP-INSTALL-ARGUMENTS...      e.g. scripts/install.sh -e '.[mesh]'
# The installer is uv when it can be had: on PATH, already in the venv, or bootstrapped into the venv from
# PyPI with the interpreter's own pip (one wheel, ~2 s CPU). uv resolves and links the 45 wheels of `make demo`
# from its cache in ~3.6 s CPU where pip took ~22 s CPU (it unpacks and byte-compiles every file;
# docs/performance.md). Without uv (offline and not cached, or MECHVERIFY_INSTALLER=pip) it is pip, as before:
# the venv gets pip (ensurepip), pip is upgraded (Python 3.11's bundled pip 23.2 took twice as long).
# Environment: VENV (default .venv), PYTHON (default python3), MECHVERIFY_INSTALLER=pip|uv (default: uv if
# it can be had, else pip). A venv made by uv has no pip of its own: `.venv/bin/python -m ensurepip` adds it.
# uv does not read pip's configuration (pip.conf, PIP_INDEX_URL ...): give a private index as UV_INDEX_URL /
# UV_EXTRA_INDEX_URL, or install with MECHVERIFY_INSTALLER=pip.
set -euo pipefail
VENV=${VENV:-.venv}
PYTHON=${PYTHON:-python3}
py=$VENV/bin/python
want=${MECHVERIFY_INSTALLER:-}

uv=""
if [ "$want" != pip ]; then
  if [ -x "$VENV/bin/uv" ]; then uv=$VENV/bin/uv
  elif command -v uv >/dev/null 2>&1; then uv=$(command -v uv)
  fi
fi

if [ ! -x "$py" ]; then
  if [ -n "$uv" ]; then
    "$uv" venv -q --python "$(command -v "$PYTHON")" "$VENV"
  else
    "$PYTHON" -m venv --without-pip "$VENV"   # pip is added below only if uv cannot be had (ensurepip: ~4 s)
  fi
fi

if [ -z "$uv" ] && [ "$want" != pip ]; then
  # Bootstrap uv: the base interpreter's pip installs the uv wheel into the venv (pip >= 22.3 has --python).
  if "$PYTHON" -m pip --python "$py" install -q "uv>=0.5,<1" >/dev/null 2>&1; then
    uv=$VENV/bin/uv
  elif "$py" -m pip --version >/dev/null 2>&1 && "$py" -m pip install -q "uv>=0.5,<1" >/dev/null 2>&1; then
    uv=$VENV/bin/uv
  elif [ "$want" = uv ]; then
    echo "scripts/install.sh: uv could not be installed (MECHVERIFY_INSTALLER=uv)" >&2
    exit 1
  else
    echo "scripts/install.sh: uv could not be installed; installing with pip" >&2
  fi
fi

if [ -n "$uv" ]; then
  # uv leaves byte-compilation to Python's first import of each module (only what is used: the demo compiles
  # ~3 s CPU of it, pip compiles every installed file, ~13 s); with PYTHONDONTWRITEBYTECODE set nothing would
  # ever be written, and every run would compile again, so then uv compiles at install as pip does.
  compile=()
  [ -n "${PYTHONDONTWRITEBYTECODE:-}" ] && compile=(--compile-bytecode)
  echo "scripts/install.sh: installing $* into $VENV with uv (a first install downloads the wheels)" >&2
  exec "$uv" pip install -q ${compile[@]+"${compile[@]}"} --python "$py" "$@"
fi
"$py" -m pip --version >/dev/null 2>&1 || "$py" -m ensurepip >/dev/null
"$py" -m pip install -q --upgrade pip
echo "scripts/install.sh: installing $* into $VENV with pip (a first install downloads the wheels)" >&2
exec "$py" -m pip install -q "$@"
