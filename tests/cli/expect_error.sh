#!/usr/bin/env bash
# expect_error.sh CODE REGEX -- COMMAND...
# Passes when COMMAND exits with CODE and writes exactly one line to stderr, matching REGEX.
set -u
code=$1 regex=$2
shift 3
err=$(mktemp)
"$@" >/dev/null 2>"$err"
got=$?
lines=$(wc -l <"$err")
msg=$(cat "$err")
rm -f "$err"
if [ "$got" -ne "$code" ]; then
  echo "FAIL: exit code $got, expected $code; stderr: $msg"; exit 1
fi
if [ "$lines" -ne 1 ]; then
  echo "FAIL: expected one line on stderr, got $lines:"; echo "$msg"; exit 1
fi
if ! grep -Eq -- "$regex" <<<"$msg"; then
  echo "FAIL: stderr does not match /$regex/: $msg"; exit 1
fi
echo "ok: $msg"
