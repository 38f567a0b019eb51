# Sourced by run.sh, robots.sh and floating.sh (from this directory): the virtual environment with
# the peers' wheels, the paths into it, the compile commands of the drivers, and the count of
# instructions per call.
#
# Environment: MUJOCO_VERSION, PIN_VERSION, EIGEN_VERSION override the pinned PyPI versions;
# CC, CXX the compilers.

MUJOCO_VERSION=${MUJOCO_VERSION:-4.0.0}
PIN_VERSION=${PIN_VERSION:-4.1.0}
EIGEN_VERSION=${EIGEN_VERSION:-3.4.1}
CC=${CC:-cc}
CXX=${CXX:-c++}

# Virtual environment with the two wheels. `pin` brings Pinocchio's headers and Boost's
# (cmeel-boost) under site-packages/cmeel.prefix, and numpy; Eigen's headers come from
# cmeel-eigen, which the pin wheel does not pull in at run time.
if [ ! -x .venv/bin/python ]; then
  python3 -m venv .venv
fi
site=$(.venv/bin/python -c "import sysconfig; print(sysconfig.get_paths()['purelib'])")
if ! .venv/bin/python -c "import mujoco, pinocchio, numpy" 2>/dev/null ||
  [ ! -e "$site/cmeel.prefix/include/eigen3/Eigen/Core" ]; then
  .venv/bin/pip install --quiet "mujoco==$MUJOCO_VERSION" "pin==$PIN_VERSION" "cmeel-eigen==$EIGEN_VERSION"
fi
mj_inc="$site/mujoco/include"
mj_lib=$(ls "$site"/mujoco/libmujoco.so* | head -n 1)
prefix="$site/cmeel.prefix"
for f in "$mj_inc/mujoco/mujoco.h" "$mj_lib" "$prefix/include/pinocchio/algorithm/aba.hpp" \
  "$prefix/include/eigen3/Eigen/Core" "$prefix/include/boost/variant.hpp"; do
  [ -e "$f" ] || { echo "missing: $f" >&2; exit 1; }
done
mkdir -p build

# stale BINARY SOURCE...: true when BINARY is missing or older than a source.
stale() { [ ! -x "$1" ] || [ -n "$(find "${@:2}" -newer "$1")" ]; }

# build_mujoco SOURCE OUT: a C driver against the wheel's libmujoco.
build_mujoco() {
  echo "building $2" >&2
  "$CC" -O3 -march=native -std=gnu11 -Wall -Wextra -I"$mj_inc" "$1" "$mj_lib" \
    -Wl,-rpath,"$(dirname "$mj_lib")" -lquadmath -lm -o "$2"
}

# build_pinocchio SOURCE OUT [LINK FLAGS...]: a C++ driver with Pinocchio compiled header-only.
build_pinocchio() {
  echo "building $2 (header-only Pinocchio, a few minutes)" >&2
  # The definitions are those Pinocchio's CMake package exports for its header-only target.
  "$CXX" -O3 -march=native -std=c++17 -DNDEBUG \
    -DBOOST_MPL_LIMIT_LIST_SIZE=30 -DBOOST_MPL_LIMIT_VECTOR_SIZE=30 \
    -DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS -DBOOST_FUSION_INVOKE_MAX_ARITY=12 \
    -w -I"$prefix/include" -I"$prefix/include/eigen3" "$1" -lquadmath "${@:3}" -o "$2"
}

# instructions COMMAND...: the instructions COMMAND runs, counted by callgrind.
instructions() {
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 |
    grep -o 'refs: *[0-9,]*' | tr -d ', ' | cut -d: -f2
}

# counts_line SIDE ROBOT LABEL CALLS: a line of robots_report.py's counts, the instructions per
# call of one side's label: those of 3·CALLS calls less those of CALLS calls, over 2·CALLS
# (start-up cancels). `count_calls SIDE ROBOT LABEL N`, the calling script's, prints the
# instructions of N calls.
counts_line() {
  local few many
  few=$(count_calls "$1" "$2" "$3" "$4")
  many=$(count_calls "$1" "$2" "$3" $((3 * $4)))
  printf '%s\t%s\t%s\t%d\n' "$1" "$2" "$3" $(((many - few) / (2 * $4)))
}
