#!/usr/bin/env bash
# cmake --install into a scratch prefix, then the README's pipeline from PATH alone: mesh a
# sample geometry, run a sample case that takes its material from the installed library, and
# post-process it (Install.ToolsRunFromThePrefix).
set -euo pipefail
build="$1"
prefix=$(mktemp -d)
work=$(mktemp -d)
trap 'rm -rf "$prefix" "$work"' EXIT
cmake --install "$build" --prefix "$prefix" > /dev/null
export PATH="$prefix/bin:$PATH"
share="$prefix/share/gsph"
for f in bin/gsph-preproc bin/gsph-solve bin/gsph-post share/gsph/materials/ofhc_copper.toml \
         share/gsph/geometries/taylor_bar.geo share/gsph/cases/taylor_bar/case.toml \
         share/doc/gsph/README.md share/doc/gsph/formats.md; do
  [ -e "$prefix/$f" ] || { echo "install_check: $f is not installed" >&2; exit 1; }
done
cd "$work"
gsph-preproc "$share/geometries/taylor_bar.geo" --set n=4 --set nr=2 --set nz=12 -o bar.h5 -q
# The Taylor case, short, naming its material by the library's file name alone: gsph-solve
# finds it in the prefix's material library.
sed -e 's/^end_time = .*/end_time = 2.0e-7/' -e 's/^output_interval = .*/output_interval = 1.0e-7/' \
    -e 's#^file = .*#file = "ofhc_copper.toml"#' "$share/cases/taylor_bar/case.toml" > case.toml
grep -q '^file = "ofhc_copper.toml"' case.toml
env -u GSPH_MATERIALS_DIR gsph-solve case.toml --particles bar.h5 -o run > solve.log
grep -q "^done: t = 2.0000e-07 s" solve.log || { echo "install_check: solve did not finish" >&2; cat solve.log >&2; exit 1; }
gsph-post run --no-pictures > post.log
[ -f run/post/run.pvd ] || { echo "install_check: no run.pvd" >&2; exit 1; }
echo "install_check: tools, materials, geometries, cases and docs installed and run from $prefix"
