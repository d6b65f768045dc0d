#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The C ABI against its checked-in baseline (abi/libgazelod.so.1.abi), with libabigail's abidiff
# (Debian abigail-tools). Fails on an incompatible change (a removed function, a changed struct
# or signature) unless the library's major version (its SONAME) changed too; additions pass.
#   bash scripts/abi-check.sh BUILT_LIBRARY          check (CTest: abi_check)
#   bash scripts/abi-check.sh --update BUILT_LIBRARY write a new baseline (after a major bump)
set -euo pipefail
cd "$(dirname "$0")/.."
update=0
if [[ ${1:-} == --update ]]; then update=1; shift; fi
lib=${1:?usage: abi-check.sh [--update] path/to/libgazelod.so.N}
# The baseline and public headers (overridable for the script's own test, abi_check_selftest).
baseline=${GAZELOD_ABI_BASELINE:-abi/libgazelod.so.1.abi}
headers=${GAZELOD_ABI_HEADERS:-include/gazelod}
command -v abidiff >/dev/null || { echo "abi-check: abidiff not found (apt-get install abigail-tools)" >&2; exit 2; }
if [[ $update == 1 ]]; then
  abidw --headers-dir "$headers" --drop-private-types --drop-undefined-syms --no-corpus-path \
    --no-comp-dir-path --out-file "$baseline" "$lib"
  echo "abi-check: wrote $baseline"
  exit 0
fi
set +e
abidiff --headers-dir2 "$headers" "$baseline" "$lib" > "${TMPDIR:-/tmp}/abi-check.$$" 2>&1
rc=$?
set -e
report=$(cat "${TMPDIR:-/tmp}/abi-check.$$")
rm -f "${TMPDIR:-/tmp}/abi-check.$$"
echo "$report"
# abidiff's status is a bit field: 1 error, 2 usage, 4 some ABI change, 8 an incompatible one.
# Its "incompatible" covers removals only, so every change that is not an addition counts: a
# function removed or changed (a struct it reaches grew, a parameter changed) breaks callers.
if (( rc & 3 )); then echo "abi-check: abidiff failed ($rc)" >&2; exit 2; fi
breaking=0
if (( rc & 8 )); then breaking=1; fi
if echo "$report" | grep -Eq '(Functions|Variables) changes summary: ([1-9][0-9]* Removed|[0-9]+ Removed, [1-9][0-9]* Changed)'; then
  breaking=1
fi
if (( breaking )); then
  old=$(grep -o "soname='[^']*'" "$baseline" | head -n1 | sed "s/soname='\(.*\)'/\1/")
  new=$(objdump -p "$lib" | awk '/SONAME/ {print $2}')
  if [[ -n $old && $old != "$new" ]]; then
    echo "abi-check: incompatible change with a new major version ($old -> $new): update the baseline (--update)"
    exit 0
  fi
  echo "abi-check: FAIL: an incompatible change to the C ABI without a major version bump ($new)" >&2
  exit 1
fi
if (( rc & 4 )); then echo "abi-check: compatible additions (the baseline can be updated with --update)"; fi
echo "abi-check: PASS"
