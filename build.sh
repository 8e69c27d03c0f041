#!/usr/bin/env bash
# The repository's one entry point for building and testing, on a developer's machine and in CI alike.
#
#   ./build.sh test [dotnet test arguments]   prepare, then every test (dotnet test OmronHostLink.sln -c Release)
#   ./build.sh prepare                        only install what the tests need (see TOOLS below)
#
# "test" also builds the solution and the artifacts a plant installs (build/package.sh: the Windows zips, the COM
# server's zip, the NuGet packages, in artifacts/) before the tests: the Windows tests run those builds under Wine, and
# publishing them up front keeps their publishes out of the parallel test run.
#
# "prepare" installs each missing tool with apt-get when run as root, and otherwise stops with one message naming the
# command to run; it restores the Sparkplug tests' npm packages (npm ci, only when package-lock.json changed) and
# checks the golden vectors against ../shared when it is there. Nothing else has to be run first on a fresh clone.
set -euo pipefail
cd "$(dirname "$0")"

# What the tests need from the system, one line each: Debian package, then the command that shows it is installed.
# Add a tool here (and nowhere else) when a test starts to need one.
TOOLS=(
  "socat socat"                          # real pseudo-terminal pairs for the serial tests
  "mosquitto mosquitto"                  # the MQTT broker the gateway tests start per test
  "mosquitto-clients mosquitto_sub"      # its command-line clients
  "nodejs node"                          # Eclipse Tahu's JavaScript Sparkplug B library decodes the gateway's payloads
  "npm npm"                              # restores that library (tests/OmronHostLink.Gateway.Tests/Sparkplug/Tahu)
  "chromium chromium"                    # the headless browser the gateway's status page is tested in
  "chromium-driver chromedriver"         # its WebDriver, which the status-page tests drive it through (Selenium)
  "tshark tshark"                        # Wireshark's console runs the repository's Host Link dissector (tools/wireshark)
)

# npm folders whose packages the tests load, restored with npm ci from their package-lock.json.
NPM_FOLDERS=(
  tests/OmronHostLink.Gateway.Tests/Sparkplug/Tahu
)

install_tools() {
  local missing=() entry package command
  for entry in "${TOOLS[@]}"; do
    read -r package command <<<"$entry"
    if ! PATH="$PATH:/usr/sbin:/usr/local/sbin" command -v "$command" >/dev/null 2>&1; then
      missing+=("$package")
    fi
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    return
  fi
  if [ "$(id -u)" -ne 0 ] || ! command -v apt-get >/dev/null 2>&1; then
    echo "error: the tests need ${missing[*]}; install them first (Debian/Ubuntu: sudo apt-get install ${missing[*]}), then run ./build.sh test again." >&2
    exit 1
  fi
  echo "Installing ${missing[*]}"
  apt-get update -qq
  # wireshark-common (tshark's) asks whether non-root users may capture packets; the tests only read capture files: no.
  echo "wireshark-common wireshark-common/install-setuid boolean false" | debconf-set-selections
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

restore_npm() {
  local folder stamp
  for folder in "${NPM_FOLDERS[@]}"; do
    stamp="$folder/node_modules/.package-lock.json"
    if [ -f "$stamp" ] && [ ! "$folder/package-lock.json" -nt "$stamp" ]; then
      continue
    fi
    echo "npm ci in $folder"
    (cd "$folder" && npm ci --no-audit --no-fund --loglevel=error)
  done
}

# The tests read tests/OmronHostLink.Testing/Vectors/vectors.json; it must be byte for byte the shared one.
check_vectors() {
  local vectors=tests/OmronHostLink.Testing/Vectors/vectors.json shared=../shared/hostlink/vectors.json
  if [ ! -f "$shared" ]; then
    echo "Golden vectors: $shared not found; using the repository's copy unchecked"
    return
  fi
  if ! cmp -s "$shared" "$vectors"; then
    echo "error: $vectors differs from $shared (the source of truth); copy it over:" >&2
    echo "  cp $shared $vectors" >&2
    diff "$shared" "$vectors" | head -40 >&2 || true
    exit 1
  fi
  echo "Golden vectors: $vectors equals $shared"
}

prepare() {
  install_tools
  restore_npm
  check_vectors
  # The Windows test bed (Wine, with its i386 half for the x86 COM server, and the Windows .NET runtime in a prefix)
  # has steps no package list covers; build/wine-bed.sh installs and checks it, and says what it could not prepare.
  bash build/wine-bed.sh
}

run_tests() {
  export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
  local log status passed failed skipped
  log=$(mktemp)
  set +e
  dotnet test OmronHostLink.sln -c Release "$@" 2>&1 | tee "$log"
  status=${PIPESTATUS[0]}
  set -e
  passed=$(grep -Eo 'Passed: +[0-9]+' "$log" | awk '{s+=$2} END {print s+0}')
  failed=$(grep -Eo 'Failed: +[0-9]+' "$log" | awk '{s+=$2} END {print s+0}')
  skipped=$(grep -Eo 'Skipped: +[0-9]+' "$log" | awk '{s+=$2} END {print s+0}')
  rm -f "$log"
  echo "Tests: $passed passed, $failed failed, $skipped skipped"
  if [ "$status" -ne 0 ] || [ "$passed" -eq 0 ]; then
    exit 1
  fi
}

case "${1:-test}" in
  prepare)
    prepare
    ;;
  test)
    shift || true
    prepare
    dotnet build OmronHostLink.sln -c Release
    bash build/package.sh
    run_tests --no-build "$@"
    ;;
  *)
    echo "usage: ./build.sh [test [dotnet test arguments] | prepare]" >&2
    exit 2
    ;;
esac
