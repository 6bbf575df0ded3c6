#!/usr/bin/env bash
# Checks that the C++ sources follow .clang-format and stay within 120 columns: every tracked .cpp
# and .hpp under polyplan/ cli/ python/src/ tests/ bench/ examples/ fuzz/ (git ls-files in a git
# checkout, find otherwise), or only the FILEs given. Exits 1 when a file is not formatted or has a
# line longer than 120 columns (clang-format leaves long string literals, raw strings and some
# comments as they are: wrap those by hand), 0 when all is well, 2 when clang-format is missing
# or fails.
#
#   scripts/check_format.sh [--fix | --diff] [FILE...]
#
# --fix formats the files in place first (clang-format -i), then checks; --diff shows what
# clang-format would change in each file that is not formatted. CLANG_FORMAT
# names the binary (default: clang-format-14 if present, else clang-format); the tree is formatted
# with clang-format 14, Debian bookworm's (`apt-get install clang-format`). JOBS (nproc) clang-format
# processes run at a time.
set -euo pipefail
cd "$(dirname "$0")/.."
export LC_ALL=C.UTF-8  # columns are characters: grep and ${#line} count UTF-8 characters, not bytes
limit=120
pinned=14
dirs=(polyplan cli python/src tests bench examples fuzz)

show_diff=0
fix=0
files=()
for arg in "$@"; do
  case "$arg" in
    --diff) show_diff=1 ;;
    --fix) fix=1 ;;
    -*) echo "usage: scripts/check_format.sh [--fix | --diff] [FILE...]" >&2; exit 2 ;;
    *) files+=("$arg") ;;
  esac
done

cf=${CLANG_FORMAT:-}
if [ -z "$cf" ]; then
  if command -v clang-format-$pinned >/dev/null 2>&1; then cf=clang-format-$pinned; else cf=clang-format; fi
fi
if ! command -v "$cf" >/dev/null 2>&1; then
  echo "check_format: $cf not found; install it: apt-get install clang-format" >&2
  exit 2
fi
version=$("$cf" --version)
major=$(sed -nE 's/.*version ([0-9]+)\..*/\1/p' <<<"$version")
if [ "$major" != "$pinned" ]; then
  echo "check_format: warning: $version; the tree is formatted with clang-format $pinned, and another" \
    "version may disagree on a few lines" >&2
fi
[ -f .clang-format ] || { echo "check_format: no .clang-format in $(pwd)" >&2; exit 2; }

# The files: tracked ones in a git checkout, else all found; those deleted in the work tree are skipped.
if [ ${#files[@]} -eq 0 ]; then
  if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    patterns=()
    for d in "${dirs[@]}"; do patterns+=("$d/*.cpp" "$d/*.hpp"); done
    while IFS= read -r -d '' f; do [ -f "$f" ] && files+=("$f"); done < <(git ls-files -z -- "${patterns[@]}")
  else
    existing=()
    for d in "${dirs[@]}"; do [ -d "$d" ] && existing+=("$d"); done
    if [ ${#existing[@]} -gt 0 ]; then
      while IFS= read -r -d '' f; do files+=("$f"); done < <(
        find "${existing[@]}" -type f \( -name '*.cpp' -o -name '*.hpp' \) -print0 | sort -z)
    fi
  fi
fi
if [ ${#files[@]} -eq 0 ]; then
  echo "check_format: no C++ files found" >&2
  exit 1
fi

# clang-format, JOBS processes at a time on batches of files (one process per file would take ten
# times as long: each start costs 0.1 s), each batch's report in a file of its own. With
# --ferror-limit=1 a file that is not formatted gives one three-line report: FILE:LINE:COL: error:
# code should be clang-formatted, its source line and a caret; anything else is unexpected.
if ! "$cf" --style=file --dump-config "${files[0]}" >/dev/null; then
  echo "check_format: $cf cannot read .clang-format" >&2
  exit 2
fi
if [ "$fix" = 1 ]; then
  printf '%s\0' "${files[@]}" | xargs -0 -n 16 -P "${JOBS:-$(nproc)}" "$cf" --style=file -i
fi
reports=$(mktemp -d)
export REPORTS=$reports
trap 'rm -rf "$reports"' EXIT
# shellcheck disable=SC2016  # $0, $$ and $@ are the inner shell's
printf '%s\0' "${files[@]}" | xargs -0 -n 32 -P "${JOBS:-$(nproc)}" sh -c \
  '"$0" --style=file --dry-run -Werror --ferror-limit=1 "$@" >>"$REPORTS/$$" 2>&1 || true' "$cf"
unformatted=$(cat "$reports"/* | sed -nE 's/^(.*):[0-9]+:[0-9]+: error: code should be clang-formatted.*/\1/p' | sort -u)
unexpected=$(cat "$reports"/* | awk '/: error: code should be clang-formatted/ { skip = 2; next }
  skip > 0 { skip--; next }
  { print }')
if [ -n "$unexpected" ]; then
  echo "check_format: $cf failed:" >&2
  echo "$unexpected" >&2
  exit 2
fi

# Lines over the limit, as FILE:LINE:TEXT.
long=$(grep -HnE "^.{$((limit + 1)),}" -- "${files[@]}" || true)

status=0
if [ -n "$unformatted" ]; then
  status=1
  echo "check_format: $(wc -l <<<"$unformatted") of ${#files[@]} files are not formatted as .clang-format says:"
  while IFS= read -r f; do
    echo "  $f"
    if [ "$show_diff" = 1 ]; then
      "$cf" --style=file "$f" | diff -u --label "$f" --label "$f (formatted)" "$f" - | sed 's/^/    /' || true
    fi
  done <<<"$unformatted"
  echo "  fix: $cf -i FILE (scripts/check_format.sh --fix formats every file; --diff shows the changes)"
fi
if [ -n "$long" ]; then
  status=1
  echo "check_format: $(wc -l <<<"$long") lines are longer than $limit columns (wrap them by hand:" \
    "split a string literal in two, \"a\" \"b\" or R\"(a)\" R\"(b)\", or move a comment above its line):"
  while IFS= read -r hit; do
    file=${hit%%:*} rest=${hit#*:}
    text=${rest#*:}
    echo "  $file:${rest%%:*}: ${#text} columns"
  done <<<"$long"
fi
if [ "$status" = 0 ]; then
  echo "check_format: ${#files[@]} files formatted and within $limit columns ($version)"
fi
exit "$status"
