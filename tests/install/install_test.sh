#!/usr/bin/env bash
# The installed hdprior: `cmake --install` into a temporary prefix (mode install), or the .deb that
# cpack builds unpacked into a temporary root (mode deb); either way the binary, its desktop entry and
# icon must be in place, `hdprior --version` and `hdprior info LOG` must run from there, and the
# .deb must depend on the runtime packages of scripts/install-deps.sh. Fails, never skips.
#   install_test.sh install|deb BUILD_DIR SHARED_DATA VERSION  (HDPRIOR_SHARED_DATA overrides SHARED_DATA)
set -euo pipefail
mode=$1 build=$(realpath "$2") version=$4
log=${HDPRIOR_SHARED_DATA:-$3}/av2/7fab2350-7eaf-3b7e-a39d-6937a4c1bede

tmp=$(mktemp -d /tmp/hdprior-install-test.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
[[ -d $log/sensors/lidar ]] || fail "the shared Argoverse 2 log is missing: expected it at $log (set HDPRIOR_SHARED_DATA)"

case $mode in
  install)
    cmake --install "$build" --prefix "$tmp/root/usr" >"$tmp/install.log" || fail "cmake --install: $(cat "$tmp/install.log")"
    ;;
  deb)
    (cd "$tmp" && cpack --config "$build/CPackConfig.cmake" -B "$tmp/package" >"$tmp/cpack.log" 2>&1) ||
      fail "cpack: $(cat "$tmp/cpack.log")"
    deb=$(find "$tmp/package" -maxdepth 1 -name "hdprior_${version}_*.deb")
    [[ -f $deb ]] || fail "no hdprior_${version}_*.deb in $(ls "$tmp/package")"
    depends=$(dpkg-deb -f "$deb" Depends)
    runtime=$(sed -n 's/^runtime_packages=(\(.*\))$/\1/p' "$(dirname "$0")/../../scripts/install-deps.sh")
    for p in $runtime libosmesa6 libglfw3 liblz4-1 libzstd1; do
      [[ ", $depends," == *", $p"[\ ,]* ]] || fail "the .deb's Depends lacks $p: $depends"
    done
    dpkg-deb -x "$deb" "$tmp/root"
    ;;
  *) fail "mode must be install or deb, not $mode" ;;
esac

bin=$tmp/root/usr/bin/hdprior
[[ -x $bin ]] || fail "no usr/bin/hdprior"
desktop=$tmp/root/usr/share/applications/hdprior.desktop
grep -qx "Exec=hdprior view" "$desktop" || fail "$desktop: no Exec=hdprior view"
grep -qx "Icon=hdprior" "$desktop" || fail "$desktop: no Icon=hdprior"
icon=$tmp/root/usr/share/icons/hicolor/128x128/apps/hdprior.png
[[ $(head -c 8 "$icon" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] || fail "$icon is not a PNG"

# From a folder outside the repository and the build, so nothing can come from either.
cd "$tmp"
[[ $("$bin" --version) == "hdprior $version" ]] || fail "--version says '$("$bin" --version)', expected 'hdprior $version'"
"$bin" info "$log" >"$tmp/info.out" 2>"$tmp/info.err" || fail "hdprior info: $(cat "$tmp/info.err")"
grep -q "^log id: *$(basename "$log")$" "$tmp/info.out" || fail "hdprior info printed: $(cat "$tmp/info.out")"
grep -q "^first sweep: *[0-9]* points$" "$tmp/info.out" || fail "hdprior info printed: $(cat "$tmp/info.out")"
echo "ok: $mode: $bin --version and info ran"
