#!/bin/sh
# Runs bfemp on one prm file in a fresh, empty scratch working directory and
# checks how it ends.
#
#   check_input_error.sh BFEMP PRM FRAGMENT...
#       Bad input. Passes only if
#         1. bfemp exits with a non-zero status (and was not killed by a
#            signal, which would be a crash rather than a message),
#         2. its stderr contains the file name of PRM,
#         3. its stderr contains every FRAGMENT (fixed strings, e.g. the
#            subsection, the entry and what is allowed),
#         4. the scratch working directory is still empty afterwards: no
#            output folder (the default "output/<run name>") or file was
#            written.
#
#   check_input_error.sh --option OPTION BFEMP PRM FRAGMENT...
#       The same for 'bfemp OPTION PRM' (a header line "# option: OPTION"
#       in the prm file, e.g. --fe-reference).
#
#   check_input_error.sh --expect-success BFEMP PRM
#       Positive control. Passes only if bfemp exits with status 0 and wrote
#       its output folder "output/" (non-empty) into the scratch directory,
#       i.e. the opposite of checks 1 and 4 holds for a valid scene.
#
# On failure it prints every check that failed, the exit status, bfemp's
# stdout and stderr and the files left behind, and a one-line summary
# "check_input_error: FAILED CHECKS: ..." listing the failed checks by name.

mode=error
if [ "$1" = "--expect-success" ]; then
  mode=success
  shift
fi
# --option OPTION: run 'bfemp OPTION PRM' (e.g. --fe-reference)
option=
if [ "$1" = "--option" ]; then
  option=$2
  shift 2
fi
if [ $# -lt 2 ] || { [ "$mode" = error ] && [ $# -lt 3 ]; }; then
  echo "usage: $0 BFEMP PRM FRAGMENT..." >&2
  echo "       $0 --expect-success BFEMP PRM" >&2
  exit 2
fi
bfemp=$1
prm=$2
shift 2

if [ ! -x "$bfemp" ]; then
  echo "check_input_error: bfemp executable '$bfemp' not found or not executable (build the target bfemp first)" >&2
  exit 2
fi
# bfemp runs in the scratch directory: make relative paths absolute.
case $bfemp in /*) ;; *) bfemp=$(pwd)/$bfemp ;; esac
case $prm in /*) ;; *) prm=$(pwd)/$prm ;; esac
prm_name=${prm##*/}

scratch=$(mktemp -d "${TMPDIR:-/tmp}/bfemp_input.XXXXXX" 2>/dev/null) ||
  { scratch=${TMPDIR:-/tmp}/bfemp_input.$$ && mkdir "$scratch"; } ||
  { echo "check_input_error: cannot create a scratch directory" >&2; exit 2; }
trap 'rm -rf "$scratch"' EXIT
trap 'exit 130' INT TERM HUP
work=$scratch/work
mkdir "$work" || exit 2

echo "check_input_error: running '$bfemp' $option '$prm' in $work"
if [ -n "$option" ]; then
  (cd "$work" && exec "$bfemp" "$option" "$prm") >"$scratch/stdout" 2>"$scratch/stderr"
else
  (cd "$work" && exec "$bfemp" "$prm") >"$scratch/stdout" 2>"$scratch/stderr"
fi
status=$?
left_behind=$(cd "$work" && find . ! -name . | sort)

failed=
fail() { # fail CHECK-NAME EXPLANATION
  failed="$failed $1"
  echo "  FAILED $1: $2"
}

if [ "$mode" = success ]; then
  [ "$status" -eq 0 ] ||
    fail exit-status "bfemp exited with status $status, expected 0 for a valid scene"
  if [ ! -d "$work/output" ] || [ -z "$(ls -A "$work/output")" ]; then
    fail output-written "no non-empty output folder 'output' was written in the working directory"
  fi
else
  if [ "$status" -eq 0 ]; then
    fail exit-status "bfemp exited with status 0, expected non-zero for bad input"
  elif [ "$status" -ge 128 ]; then
    fail exit-status "bfemp was killed by signal $((status - 128)) (a crash, not an error message)"
  fi
  grep -F -e "$prm_name" "$scratch/stderr" >/dev/null ||
    fail stderr-names-file "stderr does not name the prm file '$prm_name'"
  missing=0
  for fragment in "$@"; do
    if ! grep -F -e "$fragment" "$scratch/stderr" >/dev/null; then
      [ "$missing" -eq 0 ] && fail stderr-fragments "stderr lacks expected fragment(s):"
      missing=$((missing + 1))
      echo "      missing: $fragment"
    fi
  done
  [ -z "$left_behind" ] ||
    fail output-left-behind "bfemp wrote files although the input is bad"
fi

if [ -z "$failed" ]; then
  if [ "$mode" = success ]; then
    echo "check_input_error: PASSED: exit status 0, wrote:"
    echo "$left_behind" | sed 's/^/    /'
  else
    echo "check_input_error: PASSED: exit status $status, no output written, stderr:"
    sed 's/^/    /' "$scratch/stderr"
  fi
  exit 0
fi

echo "---- exit status: $status"
echo "---- stdout:"
sed 's/^/    /' "$scratch/stdout"
echo "---- stderr:"
sed 's/^/    /' "$scratch/stderr"
echo "---- files left in the working directory:"
if [ -n "$left_behind" ]; then echo "$left_behind" | sed 's/^/    /'; else echo "    (none)"; fi
echo "check_input_error: FAILED CHECKS:$failed"
exit 1
