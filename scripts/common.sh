# Sourced by the test scripts: run from the repository top, with a private
# temporary directory $tmp removed on exit.  Usage: sf_name=NAME; . scripts/common.sh
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
tmp=$(mktemp -d "/tmp/sf-${sf_name:-test}.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM   # a killed script stops (the EXIT trap cleans up), not carry on
scene_val() {   # scene_val FILE KEY: the key's value in a case's scene block
    awk -v k="$2" '/^```scene/ { f = 1; next } /^```/ { f = 0 } f && $1 == k && $2 == "=" { $1 = ""; $2 = ""; sub(/^ +/, ""); print; exit }' "$1"
}
in_tier() {   # in_tier FILE TIER: does `verify --tier TIER` run this case?
    t=$(scene_val "$1" tier)
    case "$2:${t:-quick}" in quick:quick | full:quick | full:full | paper:paper) return 0 ;; *) return 1 ;; esac
}
