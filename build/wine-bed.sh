#!/usr/bin/env bash
# The Windows test bed under Wine: prepares everything the COM server's and the Windows builds' tests run on, and says
# what it could not prepare. Idempotent: a second run only checks (a second or two).
#
#   bash build/wine-bed.sh            # prepare (root installs the Debian packages; apt-get update first)
#
# What it prepares, under artifacts/wine/ (git-ignored):
#   - Debian's Wine 8.0 (wine64, wine, wine64-tools for widl), MinGW-w64 for the test tools; and, for the x86 (32-bit)
#     server, wine32:i386 where it installs (dpkg --add-architecture i386). Without root, missing packages are an error.
#   - prefix/: a Wine prefix (wineboot -i) with the Windows .NET runtime of the SDK's bundled version laid out from the
#     NuGet runtime packs where the .NET installer puts it: C:\Program Files\dotnet (x64) and, with wine32,
#     C:\Program Files (x86)\dotnet (x86): host\fxr\<v>\hostfxr.dll and shared\Microsoft.NETCore.App\<v>\.
#   - tools/: scripthost-x64.exe / -x86.exe (a VBScript host with WScript.ConnectObject and WScript.Sleep, which Wine's
#     cscript lacks) and tlbcheck-x64.exe / -x86.exe (reads a registered type library back and calls the server
#     through its vtable), compiled from tests/OmronHostLink.Com.Tests/Native.
#   - bed.env: WINEPREFIX, WINE64, WINE32 (empty without wine32), X86_STATUS (ok, or why not), WINE_VERSION,
#     DOTNET_RUNTIME_VERSION; the tests read it.
# Exit status: 0 when the x64 bed is ready (x86 may be unavailable: bed.env says why), 1 otherwise.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bed="$root/artifacts/wine"
native="$root/tests/OmronHostLink.Com.Tests/Native"
mkdir -p "$bed"
export WINEDEBUG=-all DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1

started=$(date +%s)
step() { echo "wine-bed: $* ($(( $(date +%s) - started )) s)"; }

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q 'install ok installed'; }

apt_updated=false
apt_update() {
  if ! $apt_updated; then
    # An index that fails to download (a mirror being synced) is reported by apt-get update; what matters is whether
    # the packages then install, which the install below checks.
    apt-get update -qq || echo "wine-bed: apt-get update reported errors; continuing with the indexes it has"
    apt_updated=true
  fi
}

apt_install() {
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@" >"$bed/apt.log" 2>&1
}

# ---- x64 packages: required ----
required=(wine64 wine wine64-tools gcc-mingw-w64-x86-64-win32 gcc-mingw-w64-i686-win32)
missing=()
for package in "${required[@]}"; do installed "$package" || missing+=("$package"); done
if [ "${#missing[@]}" -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "wine-bed: ${missing[*]} not installed; as root: apt-get update && apt-get install ${missing[*]}" >&2
    exit 1
  fi
  step "installing ${missing[*]}"
  apt_update
  if ! apt_install "${missing[@]}"; then
    tail -20 "$bed/apt.log" >&2
    echo "wine-bed: could not install ${missing[*]}" >&2
    exit 1
  fi
fi
wine_version="$(/usr/lib/wine/wine64 --version)"
step "Wine: $wine_version"

# ---- x86: wine32 from Debian's i386 architecture, where it installs ----
x86_status_file="$bed/x86.status"
if installed wine32:i386; then
  echo ok >"$x86_status_file"
elif [ ! -f "$x86_status_file" ] || [ "$(cat "$x86_status_file")" = ok ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "wine32:i386 is not installed and this run is not root (as root: dpkg --add-architecture i386, apt-get update, apt-get install wine32:i386)" >"$x86_status_file"
  else
    step "installing wine32:i386"
    dpkg --print-foreign-architectures | grep -qx i386 || { dpkg --add-architecture i386; apt_updated=false; }
    apt_update
    if apt_install wine32:i386; then
      echo ok >"$x86_status_file"
    else
      # wine32's libraries must be the very versions of their amd64 twins (Multi-Arch: same). Where the i386 index
      # of the security suite is missing or stale, the amd64 side is newer than any i386 build apt can see: take both
      # from the release suite, pinning each pair apt names in a Breaks line to the release's version.
      extra=()
      for attempt in 1 2 3 4 5 6; do
        if apt_install -t bookworm --allow-downgrades wine32:i386 "${extra[@]}"; then
          echo ok >"$x86_status_file"
          break
        fi
        # "X:i386 ... but it is not going to be installed": ask for X:i386 by name, so apt says what holds it back.
        # " libfoo : Breaks: libfoo:i386 (!= NEWER) but RELEASE is to be installed": pin both twins to RELEASE.
        found=$(
          sed -n 's/.*Depends: \([^ ]*:i386\) .*but it is not going to be installed$/\1/p' "$bed/apt.log"
          sed -n 's/^ *\([^ :]*\) : Breaks: \1:i386 (!= [^)]*) but \([^ ]*\) is to be installed$/\1=\2 \1:i386=\2/p' "$bed/apt.log" | tr ' ' '\n'
        )
        added=false
        for item in $found; do
          case " ${extra[*]} " in *" $item "*) continue ;; esac
          # A pinned twin replaces its unpinned request.
          kept=()
          for old in "${extra[@]}"; do [ "$old" = "${item%%=*}" ] || kept+=("$old"); done
          extra=("${kept[@]}" "$item")
          added=true
        done
        $added || break
      done
      if ! installed wine32:i386; then
        {
          echo -n "wine32:i386 does not install from this machine's Debian mirror: "
          grep -E '^(E:|  *[^ ]+ : )' "$bed/apt.log" | head -5 | tr '\n' ' '
        } >"$x86_status_file"
      fi
    fi
  fi
fi
x86_status="$(cat "$x86_status_file")"
step "x86: $x86_status"

# ---- the Windows .NET runtime packs, of the SDK's bundled version ----
# The version the SDK in use (global.json's) publishes self-contained apps with, read from its bundled versions.
sdk_dir="$(dirname "$(readlink -f "$(command -v dotnet)")")/sdk/$(cd "$root" && dotnet --version)"
runtime_version="$(sed -n 's:.*<BundledNETCoreAppPackageVersion>\(.*\)</BundledNETCoreAppPackageVersion>.*:\1:p' "$sdk_dir/Microsoft.NETCoreSdk.BundledVersions.props" 2>/dev/null)"
[ -n "$runtime_version" ] || runtime_version="$(dotnet msbuild "$root/build/wine/runtime-packs.proj" -getProperty:BundledNETCoreAppPackageVersion)"
packs="$bed/packs"
rids=(win-x64)
[ "$x86_status" = ok ] && rids+=(win-x86)
for rid in "${rids[@]}"; do
  if [ ! -f "$packs/microsoft.netcore.app.runtime.$rid/$runtime_version/runtimes/$rid/native/hostfxr.dll" ]; then
    step "restoring Microsoft.NETCore.App.Runtime.$rid $runtime_version"
    dotnet restore "$root/build/wine/runtime-packs.proj" -p:RuntimePackVersion="$runtime_version" -p:RuntimePackRids="${rids[*]}" --packages "$packs" -v q
    break
  fi
done

# ---- the prefix ----
export WINEPREFIX="$bed/prefix" WINEARCH=win64
wine64=/usr/lib/wine/wine64
wine32=""
[ "$x86_status" = ok ] && wine32=/usr/lib/wine/wine
prefix_stamp="$WINEPREFIX/.omronhostlink-bed"
want_stamp="$wine_version runtime $runtime_version x86 ${x86_status:0:2}"
if [ ! -f "$prefix_stamp" ] || [ "$(cat "$prefix_stamp")" != "$want_stamp" ]; then
  step "creating the prefix $WINEPREFIX"
  wineserver -k 2>/dev/null || true
  rm -rf "$WINEPREFIX"
  "$wine64" wineboot -i >/dev/null 2>&1
  wineserver -w
  lay() { # rid, destination: the runtime as the .NET installer lays it out
    local pack="$packs/microsoft.netcore.app.runtime.$1/$runtime_version/runtimes/$1"
    local dest="$2"
    mkdir -p "$dest/host/fxr/$runtime_version" "$dest/shared/Microsoft.NETCore.App/$runtime_version"
    cp "$pack/native/hostfxr.dll" "$dest/host/fxr/$runtime_version/"
    cp "$pack/lib/net10.0/"* "$pack/native/"* "$dest/shared/Microsoft.NETCore.App/$runtime_version/"
    rm "$dest/shared/Microsoft.NETCore.App/$runtime_version/hostfxr.dll"
  }
  lay win-x64 "$WINEPREFIX/drive_c/Program Files/dotnet"
  [ "$x86_status" = ok ] && lay win-x86 "$WINEPREFIX/drive_c/Program Files (x86)/dotnet"
  echo "$want_stamp" >"$prefix_stamp"
fi

# ---- the test tools ----
tools="$bed/tools"
mkdir -p "$tools"
build_tool() { # name, arch-suffix, compiler, extra sources/flags...
  local name="$1" arch="$2" cc="$3"
  shift 3
  local out="$tools/$name-$arch.exe"
  if [ ! -f "$out" ] || [ -n "$(find "$native" -newer "$out" -name '*.[ch]' -o -newer "$out" -name '*.idl' | head -1)" ]; then
    step "compiling $name-$arch.exe"
    "$cc" -municode -O2 -Wall -Wextra -Wno-unused-parameter -Werror -o "$out" "$@" -lole32 -loleaut32 -luuid -luser32
  fi
}
build_tool scripthost x64 x86_64-w64-mingw32-gcc "$native/scripthost.c"
build_tool scripthost x86 i686-w64-mingw32-gcc "$native/scripthost.c"
idl="$root/src/OmronHostLink.Com/OmronHostLink.Com.idl"
if [ ! -f "$tools/OmronHostLink.Com.h" ] || [ "$idl" -nt "$tools/OmronHostLink.Com.h" ]; then
  widl -I /usr/include/wine/wine/windows -h -o "$tools/OmronHostLink.Com.h" "$idl"
  touch -d '1 minute ago' "$tools/OmronHostLink.Com.h"
  rm -f "$tools"/tlbcheck-*.exe
fi
build_tool tlbcheck x64 x86_64-w64-mingw32-gcc -I "$tools" "$native/tlbcheck.c"
build_tool tlbcheck x86 i686-w64-mingw32-gcc -I "$tools" "$native/tlbcheck.c"

cat >"$bed/bed.env" <<EOF
WINEPREFIX=$WINEPREFIX
WINE64=$wine64
WINE32=$wine32
X86_STATUS=$x86_status
WINE_VERSION=$wine_version
DOTNET_RUNTIME_VERSION=$runtime_version
TOOLS=$tools
EOF
step "ready: $bed/bed.env"
