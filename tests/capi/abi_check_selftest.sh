#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# scripts/abi-check.sh can fail: two builds of a tiny library, the second changing a public
# struct's layout, must be refused with the same SONAME and let through with a new one; an
# added function must pass. (CTest: abi_check_selftest.)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=${1:?usage: abi_check_selftest.sh WORK_DIR}
rm -rf "$work" && mkdir -p "$work/h1" "$work/h2" "$work/h3"
cat > "$work/h1/t.h" <<'H'
typedef struct t_pose { double x, y; } t_pose;
int t_get(const t_pose* p);
H
cat > "$work/h2/t.h" <<'H'
typedef struct t_pose { double x, y, z; } t_pose;
int t_get(const t_pose* p);
H
cat > "$work/h3/t.h" <<'H'
typedef struct t_pose { double x, y; } t_pose;
int t_get(const t_pose* p);
int t_more(void);
H
body='#include "t.h"
int t_get(const t_pose* p) { return p ? 1 : 0; }'
build() {  # build DIR SONAME [extra source]
  printf '%s\n%s\n' "$body" "${3:-}" > "$work/$1/t.c"
  cc -g -shared -fPIC -Wl,-soname,"$2" -I"$work/$1" -o "$work/$1/$2" "$work/$1/t.c"
}
build h1 libt.so.1
build h2 libt.so.1
build h3 libt.so.1 'int t_more(void) { return 2; }'
export GAZELOD_ABI_BASELINE=$work/base.abi
GAZELOD_ABI_HEADERS=$work/h1 bash "$root/scripts/abi-check.sh" --update "$work/h1/libt.so.1" >/dev/null
check() {  # check WANT_STATUS HEADERS LIB
  set +e
  GAZELOD_ABI_HEADERS=$2 bash "$root/scripts/abi-check.sh" "$3" > "$work/out.txt" 2>&1
  local got=$?
  set -e
  if [[ $got != "$1" ]]; then
    cat "$work/out.txt"
    echo "abi_check_selftest: FAIL: $3 gave status $got, expected $1" >&2
    exit 1
  fi
}
check 0 "$work/h1" "$work/h1/libt.so.1"  # unchanged
check 1 "$work/h2" "$work/h2/libt.so.1"  # layout changed, same major: refused
check 0 "$work/h3" "$work/h3/libt.so.1"  # a function added: compatible
mkdir -p "$work/h4" && cp "$work/h2/t.h" "$work/h4/"
build h4 libt.so.2
check 0 "$work/h4" "$work/h4/libt.so.2"  # layout changed with a new major version
echo "abi_check_selftest: PASS"
