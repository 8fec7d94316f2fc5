#!/usr/bin/env bash
# output_safety.sh GRANPIPE EXPECT PIPELINE WORKDIR
# What --out and --overwrite refuse, as a hostile tester would try it: exit 2, one line,
# and nothing of the user's changed. PIPELINE is a small sweep (lattice_packing.json).
set -eu
exe=$1 expect=$2 pipeline=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)

# sum DIR: one line per file below DIR with its checksum, to compare before and after.
sum() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 md5sum); }
unchanged() {  # unchanged DIR SUMFILE WHAT
  sum "$1" | cmp -s - "$2" || { echo "FAIL: $3 changed $1"; exit 1; }
}

"$exe" "$pipeline" --quiet --out "$work/earlier"
sum "$work/earlier" >"$work/earlier.sum"

# A user's folder that merely looks like a granpipe output.
mkdir "$work/users"
echo '{"mine": true}' >"$work/users/pipeline.json"
echo "notes" >"$work/users/notes.txt"
sum "$work/users" >"$work/users.sum"
"$expect" 2 "users: --overwrite replaces only directories granpipe made \(they hold a \.granpipe-run file\), got one without" \
  -- "$exe" "$pipeline" --quiet --out "$work/users" --overwrite
"$expect" 2 "users: expected a new or empty output directory, got a non-empty one that granpipe did not make" \
  -- "$exe" "$pipeline" --quiet --out "$work/users"
unchanged "$work/users" "$work/users.sum" "a refused --overwrite"

# The working directory, its parent, the home directory and / are never output directories.
(cd "$work/users" && "$expect" 2 "^granpipe: \.: expected a directory of the run's own, got $work/users, which is the working directory" \
  -- "$exe" "$pipeline" --quiet --out . --overwrite)
(cd "$work/users" && "$expect" 2 "^granpipe: \.\.: expected a directory of the run's own, got $work, which holds the working directory" \
  -- "$exe" "$pipeline" --quiet --out .. --overwrite)
mkdir -p "$work/home/me"
HOME=$work/home/me "$expect" 2 "home: expected a directory of the run's own, got $work/home, which holds the home directory" \
  -- "$exe" "$pipeline" --quiet --out "$work/home" --overwrite
"$expect" 2 "^granpipe: /: expected a directory of the run's own, got /, which is the root directory" \
  -- "$exe" "$pipeline" --quiet --out / --overwrite
unchanged "$work/users" "$work/users.sum" "--out . or .."

# A symlink, with or without a trailing slash, even to granpipe's own output.
ln -s "$work/earlier" "$work/link"
for out in "$work/link" "$work/link/" "$work/link//"; do
  "$expect" 2 "link: expected a directory, got a symlink \(to $work/earlier\); give the directory itself as --out" \
    -- "$exe" "$pipeline" --quiet --out "$out" --overwrite
done
unchanged "$work/earlier" "$work/earlier.sum" "--out through a symlink"

# A regular file is not called a directory.
echo "data" >"$work/results.txt"
"$expect" 2 "results\.txt: expected a directory, got a regular file$" -- "$exe" "$pipeline" --quiet --out "$work/results.txt"
[ "$(cat "$work/results.txt")" = "data" ] || { echo "FAIL: the file given as --out changed"; exit 1; }

# An input file inside the output directory is never deleted before it is read.
cat >"$work/reprocess.json" <<JSON
{"source": {"plugin": "h5md", "params": {"file": "$work/earlier/point_000/frames.h5"}},
 "analyzers": [{"plugin": "packing"}]}
JSON
"$expect" 2 "reprocess\.json: source\.params\.file: expected a file outside the output directory $work/earlier, got \"$work/earlier/point_000/frames\.h5\" inside it" \
  -- "$exe" "$work/reprocess.json" --quiet --out "$work/earlier" --overwrite
"$expect" 2 "reprocess\.json: source\.params\.file: expected a file outside the output directory $work/earlier/point_000, " \
  -- "$exe" "$work/reprocess.json" --quiet --out "$work/earlier/point_000" --overwrite
# Given by --set, the --set is named (the file's own path was).
"$expect" 2 "^granpipe: --set source\.params\.file=[^:]*: expected a file outside the output directory $work/earlier, " \
  -- "$exe" "$work/reprocess.json" --quiet --out "$work/earlier" --overwrite \
  --set "source.params.file=$work/earlier/point_000/frames.h5"
# An entry of a list of files, given by --set, is named by the --set and its index (it was
# "--set x=[...][0]").
cp "$work/earlier/point_000/frames.h5" "$work/outside.h5"
"$expect" 2 "^granpipe: --set source\.params\.continued_in=[^:]*: source\.params\.continued_in\[0\]: expected a file outside the output directory $work/earlier, " \
  -- "$exe" "$work/reprocess.json" --quiet --out "$work/earlier" --overwrite \
  --set "source.params.file=$work/outside.h5" \
  --set "source.params.continued_in=[\"$work/earlier/point_000/frames.h5\"]"
cp "$work/reprocess.json" "$work/earlier/reprocess.json"
"$expect" 2 "earlier/reprocess\.json: expected a file outside the output directory $work/earlier, got \"$work/earlier/reprocess\.json\" inside it" \
  -- "$exe" "$work/earlier/reprocess.json" --quiet --out "$work/earlier" --overwrite
rm "$work/earlier/reprocess.json"
unchanged "$work/earlier" "$work/earlier.sum" "a run reading from its output directory"

# What a user adds to a run's folder stops --overwrite; what granpipe's report and scripts
# add is replaced with the run (they list it in the run's .granpipe-manifest).
grep -qx "report.html" "$work/earlier/.granpipe-manifest" || { echo "FAIL: report.html is not in the manifest"; exit 1; }
echo "notes" >"$work/earlier/point_001/notes.txt"
mkdir "$work/earlier/plots"
"$expect" 2 "earlier: --overwrite removes only what granpipe wrote, and this run's folder also holds plots/, point_001/notes\.txt; move them out or remove the folder yourself; nothing was changed$" \
  -- "$exe" "$pipeline" --quiet --out "$work/earlier" --overwrite
rm -r "$work/earlier/point_001/notes.txt" "$work/earlier/plots"
unchanged "$work/earlier" "$work/earlier.sum" "a refused --overwrite of a folder with a user's files"
PYTHONPATH=$(dirname "$0")/../../scripts python3 -c "import sys, result_csv; result_csv.write_csv(sys.argv[1], '# pooled', [['a'], [1]])" \
  "$work/earlier/pooled.table.csv"

# --overwrite replaces granpipe's own output, all of it, and leaves nothing beside it.
"$exe" "$pipeline" --quiet --set seed=99 --out "$work/earlier/" --overwrite
grep -q '"seed": 99' "$work/earlier/pipeline.json" || { echo "FAIL: --overwrite did not replace the run"; exit 1; }
[ -z "$(ls -d "$work"/earlier.granpipe-* 2>/dev/null)" ] || { echo "FAIL: a replaced run left a directory beside it"; exit 1; }
[ ! -e "$work/earlier/pooled.table.csv" ] || { echo "FAIL: a script's table survived --overwrite"; exit 1; }
echo "every unsafe --out refused, nothing of the user's changed"
