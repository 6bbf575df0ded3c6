#!/bin/sh
# The compiler launcher of every C++ unit (CMakeLists.txt: POLYPLAN_TIME_UNITS): runs the compile
# command it is given and appends "MILLISECONDS<TAB>OBJECT" to the file named first, so that the
# build leaves its units' compile times behind (scripts/slowest_units.sh lists the slowest).
times=$1
shift
start=$(date +%s%N)
"$@"
status=$?
end=$(date +%s%N)
object=
previous=
for argument in "$@"; do
  [ "$previous" = "-o" ] && object=$argument
  previous=$argument
done
printf '%s\t%s\n' "$(((end - start) / 1000000))" "$object" >>"$times"
exit $status
