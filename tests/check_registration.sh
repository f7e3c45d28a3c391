#!/usr/bin/env bash
# Checks that ctest runs every test case of the test binary, each as its own entry:
#  1. no test case name contains a character that breaks registration: ';' (catch_discover_tests
#     splits names on it, into entries that match nothing), '\' (Catch's test-spec escape) or a
#     leading or trailing '*' (a wildcard, so the entry could select other cases too);
#  2. every name `--list-test-names-only` prints is a ctest entry;
#  3. an entry whose name matches no test case fails (the binary refuses to run nothing).
# Usage: check_registration.sh TEST_BINARY BUILD_DIR CTEST_COMMAND
set -u
export LC_ALL=C
exe=$1 build=$2 ctest=$3
fail=0
names=$("$exe" --list-test-names-only | sed 's/\r$//' | sed '/^$/d' | sort)
count=$(printf '%s\n' "$names" | grep -c .)
if [ "$count" -lt 1 ]; then echo "FAIL: $exe lists no test cases"; exit 1; fi

bad=$(printf '%s\n' "$names" | grep -e ';' -e '\\' -e '^\*' -e '\*$')
if [ -n "$bad" ]; then
  echo "FAIL: test case names must not contain ';' or '\\', nor start or end with '*' (tests/README.md):"
  printf '  %s\n' "$bad"
  fail=1
fi

entries=$("$ctest" --test-dir "$build" -N | sed -n 's/^ *Test *#[0-9]*: //p' | sort)
missing=$(comm -23 <(printf '%s\n' "$names") <(printf '%s\n' "$entries"))
if [ -n "$missing" ]; then
  echo "FAIL: test cases with no ctest entry of their own:"
  printf '  %s\n' "$missing"
  fail=1
fi

"$exe" "registration check: a name that matches no test case" >/dev/null 2>&1
rc=$?
if [ "$rc" -eq 0 ]; then
  echo "FAIL: running a name that matches no test case exited 0; such an entry would pass by running nothing"
  fail=1
fi

[ "$fail" -eq 0 ] && echo "OK: $count test cases, each its own ctest entry; an entry that selects nothing fails (exit $rc)"
exit "$fail"
