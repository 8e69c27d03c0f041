#!/usr/bin/env bash
# Builds what a plant installs, into artifacts/ (git-ignored), with the one publish command every page names:
#
#   bash build/package.sh            (bash build/package.sh --check: does artifacts/ match the sources?)
#
#   artifacts/packages/                          the NuGet packages (dotnet pack): OmronHostLink, .DependencyInjection,
#                                                .Simulator, .Cli (the hostlink tool), with their symbol packages
#   artifacts/OmronHostLink.Gateway-VERSION-win-x64.zip   the gateway, self-contained: no .NET runtime needed
#   artifacts/hostlink-VERSION-win-x64.zip               the console tool, self-contained
#   artifacts/OmronHostLink.Com-VERSION-win.zip          the COM server: x64\ and x86\ (each needs the .NET 10 runtime
#                                                        of its bitness), register.cmd, unregister.cmd
#
# The Windows programs are published by
#   dotnet publish PROJECT -c Release -r win-x64 --self-contained -o DIR
# (linux-x64 for Linux), the command docs/install-windows.md and docs/install-linux.md show. The COM server is
# framework-dependent (a COM server runs in its caller's process, on the installed runtime) and needs Wine's widl for
# its type library (Debian: wine64-tools): without it this script fails rather than ship a server VBA cannot reference.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
out="$root/artifacts"

# What the artifacts are built from: the contents of the sources, of the build's configuration and of what the packages
# carry (README, LICENSE), tracked or not (ignored files, such as bin/ and obj/, aside). With --check the exit status
# says whether artifacts/ still matches them (the COM tests repackage when it does not); tests and docs do not count.
inputs=(src build/package.sh Directory.Build.props Directory.Build.targets Directory.Packages.props global.json README.md LICENSE)
stamp() {
  git ls-files -z --cached --others --exclude-standard -- "${inputs[@]}" 2>/dev/null | sort -z | xargs -0 -r sha256sum | sha256sum | cut -d' ' -f1
}
if [ "${1:-}" = --check ]; then
  git rev-parse --git-dir >/dev/null 2>&1 && [ -f "$out/package.stamp" ] && [ "$(cat "$out/package.stamp")" = "$(stamp)" ] \
    && compgen -G "$out/OmronHostLink.Gateway-*-win-x64.zip" >/dev/null && compgen -G "$out/hostlink-*-win-x64.zip" >/dev/null \
    && compgen -G "$out/OmronHostLink.Com-*-win.zip" >/dev/null && compgen -G "$out/packages/OmronHostLink.*.nupkg" >/dev/null
  exit
fi
source_stamp="$(stamp)"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
started=$(date +%s)
step() { echo "package: $* ($(( $(date +%s) - started )) s)"; }

for tool in zip widl; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    package=$([ "$tool" = widl ] && echo wine64-tools || echo zip)
    if [ "$(id -u)" -eq 0 ]; then
      step "installing $package"
      apt-get update -qq || true
      DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$package" >/dev/null
    else
      echo "package: $tool is missing; as root: apt-get install $package" >&2
      exit 1
    fi
  fi
done

version="$(dotnet msbuild src/OmronHostLink/OmronHostLink.csproj -t:MinVer -getProperty:MinVerVersion -p:TargetFramework=net10.0)"
step "version $version"
publish="$out/publish"
rm -rf "$publish" "$out/packages" "$out"/*.zip "$out/package.stamp"
mkdir -p "$publish"

zip_folder() { # folder, zip: the folder's contents at the zip's root
  (cd "$1" && zip -q -r -X "$2" .)
}

step "NuGet packages"
dotnet pack OmronHostLink.sln -c Release -o "$out/packages" -v q -nologo

step "gateway (win-x64, self-contained)"
dotnet publish src/OmronHostLink.Gateway -c Release -r win-x64 --self-contained -o "$publish/gateway-win-x64" -v q -nologo
zip_folder "$publish/gateway-win-x64" "$out/OmronHostLink.Gateway-$version-win-x64.zip"

step "hostlink (win-x64, self-contained)"
dotnet publish src/OmronHostLink.Cli -c Release -r win-x64 --self-contained -o "$publish/hostlink-win-x64" -v q -nologo
zip_folder "$publish/hostlink-win-x64" "$out/hostlink-$version-win-x64.zip"

step "COM server (x64 and x86)"
com="$publish/OmronHostLink.Com"
for arch in x64 x86; do
  dotnet publish src/OmronHostLink.Com -c Release -r "win-$arch" --self-contained false -p:RequireTypeLibrary=true -o "$com/$arch" -v q -nologo
  rm -f "$com/$arch"/*.pdb
done
cp src/OmronHostLink.Com/install/register.cmd src/OmronHostLink.Com/install/unregister.cmd "$com/"
zip_folder "$com" "$out/OmronHostLink.Com-$version-win.zip"

echo "$source_stamp" >"$out/package.stamp"
step "done"
ls -l "$out"/*.zip "$out/packages"
