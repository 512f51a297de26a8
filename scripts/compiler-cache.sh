# Sourced by build.sh and test.sh: when ccache is installed (it is optional,
# not a dependency), compile through it, keyed on paths relative to the
# source tree, so that another clone of the same sources on the same machine
# (a CI run) reuses the objects. Prints the cmake arguments to use.
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
  compiler_cache=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
else
  compiler_cache=()
fi
