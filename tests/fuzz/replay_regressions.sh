#!/usr/bin/env bash
# replay_regressions.sh GRANPIPE REGRESSIONS_DIR WORKDIR
# Inputs the fuzzers once crashed or hung on (docs/fuzzing.md), given to the normal
# granpipe executable: pipeline-* as `granpipe validate` (the JSON text, then a --set per
# NUL-separated part, as fuzz_pipeline splits it), frames-* as `granpipe inspect`. Each
# must exit 2 with exactly the one line of NAME.expected, where FILE stands for the input.
# `timeout` turns a hang back into a failure.
set -u
exe=$1 dir=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
failed=0
for input in "$dir"/*; do
  name=$(basename "$input")
  [[ $name == *.expected ]] && continue
  case $name in
    pipeline-*)
      parts=()
      while IFS= read -r -d '' part; do parts+=("$part"); done < <(cat "$input"; printf '\0')
      file=$work/$name.json
      printf '%s' "${parts[0]}" >"$file"
      command=("$exe" validate "$file")
      for set in "${parts[@]:1}"; do command+=(--set "$set"); done
      ;;
    frames-*)
      file=$work/$name.h5
      cp "$input" "$file"
      command=("$exe" inspect "$file" --rows 1000)
      ;;
    *) echo "FAIL: $name: expected a name starting pipeline- or frames-"; failed=1; continue ;;
  esac
  timeout 60 "${command[@]}" >/dev/null 2>"$work/stderr"
  code=$?
  message=$(cat "$work/stderr")
  message=${message//"$file"/FILE}
  expected=$(cat "$input.expected")
  if [ "$code" -ne 2 ] || [ "$(wc -l <"$work/stderr")" -ne 1 ] || [ "$message" != "$expected" ]; then
    echo "FAIL: $name: exit $code, stderr:"; echo "$message"; echo "expected exit 2 and:"; echo "$expected"
    failed=1
  else
    echo "ok: $name: $message"
  fi
done
exit $failed
