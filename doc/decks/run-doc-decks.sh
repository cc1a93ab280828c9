#!/usr/bin/env bash
# Runs every deck shown in doc/deck-reference.md (its ```xml and ```yaml blocks) and every deck in
# doc/decks/, on 1 rank and, if mpirun is found, on 3 ranks; checks the exit status and that
# the nodal/element data of the 1- and 3-rank Exodus files are identical.
#   usage: doc/decks/run-doc-decks.sh path/to/peridot [work-dir]
set -euo pipefail
peridot=$(realpath "${1:?usage: $0 path/to/peridot [work-dir]}")
here=$(cd "$(dirname "$0")" && pwd)
work=${2:-$(mktemp -d)}
mkdir -p "$work"
mpirun=$(command -v mpirun || true)
mpiflags=(--oversubscribe)
[ "$(id -u)" = 0 ] && mpiflags+=(--allow-run-as-root)

# Decks embedded in the reference, numbered in order of appearance.
python3 - "$here/../deck-reference.md" "$work" <<'EOF'
import re, sys, pathlib
text = pathlib.Path(sys.argv[1]).read_text()
for n, (lang, body) in enumerate(re.findall(r"```(xml|yaml)\n(.*?)```", text, re.S), 1):
    d = pathlib.Path(sys.argv[2]) / f"reference-{n}"
    d.mkdir(parents=True, exist_ok=True)
    (d / f"deck.{lang}").write_text(body)
EOF
for deck in "$here"/*.xml "$here"/*.yaml; do
  d="$work/$(basename "${deck%.*}")"
  mkdir -p "$d" && cp "$here"/*.txt "$deck" "$d"/
done

status=0
for d in "$work"/*/; do
  deck=$(ls "$d" | grep -E '\.(xml|yaml)$' | head -1)
  for np in 1 3; do
    [ "$np" = 3 ] && [ -z "$mpirun" ] && continue
    run="$d/np$np"; mkdir -p "$run"; cp "$d"/*.txt "$d/$deck" "$run"/ 2>/dev/null || cp "$d/$deck" "$run"/
    if [ "$np" = 1 ]; then cmd=("$peridot" "$deck"); else cmd=("$mpirun" "${mpiflags[@]}" -np 3 "$peridot" "$deck"); fi
    if (cd "$run" && "${cmd[@]}" > log.txt 2>&1); then echo "ok    $deck ($np rank(s))"; else
      echo "FAIL  $deck ($np rank(s)): see $run/log.txt"; status=1; fi
  done
  if [ -d "$d/np3" ] && command -v ncdump > /dev/null; then
    for e in "$d"/np1/*.e; do
      [ -e "$e" ] || continue
      # Global variables are sums whose last bits depend on the reduction order: skip them.
      strip() { ncdump "$1" | sed -n '/^data:/,$p' | awk '/vals_glo_var =/{skip=1} skip&&/;/{skip=0;next} !skip'; }
      if ! diff -q <(strip "$e") <(strip "$d/np3/$(basename "$e")") > /dev/null; then
        echo "DIFF  $(basename "$e"): 1 and 3 ranks differ"; status=1; fi
    done
  fi
done
echo "work directory: $work"
exit $status
