#!/bin/bash
# One impact (plane stress, nu = 0.33, half disk) with the given
# discretization; prints its summary line. Used by the comparison scripts.
#
# usage: bench/impact_case.sh DIR VELOCITY REFINEMENTS ELEMENTS GRADING
#                             PENALTY FRACTION [TIME-STEPPING LINES...]
#   e.g. bench/impact_case.sh /tmp/run 0.1 2 12 0.3 100 0.01 \
#          "set Contact mass = redistributed"
# Environment: TAU (relaxation time, default 0), DEGREE (of the elements,
# default 2). The run's full output is left in DIR/log.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=$1 v=$2 ref=$3 el=$4 grading=$5 kappa=$6 fraction=$7
shift 7
extra=$(printf '  %s\n' "$@")
[ $# -gt 0 ] || extra=""
mkdir -p "$dir"
cat > "$dir/case.prm" <<EOP
set Task             = impact
set Output directory = $dir
subsection Geometry
  set Domain             = half disk
  set Global refinements = $ref
end
subsection Material
  set Plane model     = plane stress
  set Poisson ratio   = 0.33
  set Relaxation time = ${TAU:-0}
end
subsection Finite element
  set Degree = ${DEGREE:-2}
end
subsection Contact
  set Penalty factor = $kappa
end
subsection Impact
  set Velocity                = $v
  set Elements across contact = $el
  set Grading                 = $grading
  set Output interval         = 0
  set Number of projected modes = 0
end
subsection Time stepping
  set Time step fraction = $fraction
$extra
end
EOP
build/diskimpact "$dir/case.prm" > "$dir/log"
grep -E "DoFs|epsilon|contact time|delta_max|force_max|energy error" "$dir/log" |
  tr -s ' ' | tr '\n' ';'
echo
