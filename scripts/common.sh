# Sourced by the test scripts: run from the repository top, with a private
# temporary directory $tmp removed on exit.  Usage: sf_name=NAME; . scripts/common.sh
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
tmp=$(mktemp -d "/tmp/sf-${sf_name:-test}.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
