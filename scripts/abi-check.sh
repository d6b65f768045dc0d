#!/usr/bin/env bash
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
baseline=abi/libgazelod.so.1.abi
command -v abidiff >/dev/null || { echo "abi-check: abidiff not found (apt-get install abigail-tools)" >&2; exit 2; }
if [[ $update == 1 ]]; then
  abidw --headers-dir include/gazelod --drop-private-types --drop-undefined-syms --no-corpus-path \
    --no-comp-dir-path --out-file "$baseline" "$lib"
  echo "abi-check: wrote $baseline"
  exit 0
fi
set +e
abidiff --headers-dir2 include/gazelod "$baseline" "$lib"
rc=$?
set -e
# abidiff's status is a bit field: 1 error, 2 usage, 4 some ABI change, 8 an incompatible one.
if (( rc & 3 )); then echo "abi-check: abidiff failed ($rc)" >&2; exit 2; fi
if (( rc & 8 )); then
  old=$(sed -n 's/.*soname=.\([^"'"'"']*\).*/\1/p' "$baseline" | head -n1)
  new=$(objdump -p "$lib" | awk '/SONAME/ {print $2}')
  if [[ $old != "$new" ]]; then
    echo "abi-check: incompatible change with a new major version ($old -> $new): update the baseline (--update)"
    exit 0
  fi
  echo "abi-check: FAIL: an incompatible change to the C ABI without a major version bump ($new)" >&2
  exit 1
fi
(( rc & 4 )) && echo "abi-check: compatible additions (the baseline can be updated with --update)"
echo "abi-check: PASS"
