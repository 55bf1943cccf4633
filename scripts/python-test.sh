#!/bin/sh
# The Python package (python/slipfield, ctypes over build/libslipfield.so)
# against the CLI, by pytest from Debian's python3 (the python3 first on
# PATH may not see Debian's pandas and pytest).
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
py=/usr/bin/python3
[ -x "$py" ] || py=python3
cd "$top"
PYTHONPATH="$top/python" "$py" -m pytest -q -p no:cacheprovider python/tests
st=$?
[ $st -eq 0 ] && echo "python-test: passed" || echo "python-test: FAILED ($st)" >&2
exit $st
