# Sourced by scripts/gallery and tests/browser/run.sh (after scripts/deps.sh).
# cyclide_web_deps [chromium]: makes web/node_modules match
# web/package-lock.json. Nothing is done when a stamp says the lock file has
# not changed or the installed versions already match it (so it works
# offline); otherwise `npm ci` from npm's local cache, then from the registry.
# With "chromium", also installs Debian's chromium (apt-get, through
# cyclide_ensure_packages) when /usr/bin/chromium is missing.
# True when every package in web/package-lock.json is installed at its version.
_cyclide_web_installed() {
  (cd "$1" && node -e '
    const fs = require("fs");
    const lock = JSON.parse(fs.readFileSync("package-lock.json", "utf8"));
    for (const [p, v] of Object.entries(lock.packages || {})) {
      if (!p) continue;
      let got = null;
      try { got = JSON.parse(fs.readFileSync(p + "/package.json", "utf8")).version; } catch {}
      if (got !== v.version) process.exit(1);
    }' 2>/dev/null)
}

cyclide_web_deps() {
  local web="$root/web"
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    cyclide_ensure_packages nodejs npm
  fi
  local major
  major=$(node -p 'process.versions.node.split(".")[0]')
  if [ "$major" -lt 20 ]; then
    echo "cyclide: node $(node -v) is too old for playwright-core (needs >= 20)" >&2
    return 1
  fi
  local stamp="$web/node_modules/.cyclide-lock.sha256" want
  want=$(sha256sum "$web/package-lock.json" | cut -d' ' -f1)
  if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then
    :
  elif _cyclide_web_installed "$web"; then
    echo "$want" >"$stamp"  # node_modules already holds what the lock file pins
  else
    echo "cyclide: installing the gallery's npm packages (web/package-lock.json)"
    # npm's cache first (no network), then the registry.
    if (cd "$web" && { npm ci --offline --no-audit --no-fund --loglevel=silent 2>/dev/null ||
                       npm ci --prefer-offline --no-audit --no-fund --loglevel=error \
                         --fetch-retries=1 --fetch-timeout=30000; }) &&
       _cyclide_web_installed "$web"; then
      echo "$want" >"$stamp"
    else
      echo "cyclide: could not install web/'s npm packages (npm ci failed)" >&2
      return 1
    fi
  fi
  if [ "${1:-}" = chromium ] && [ -z "${CYCLIDE_CHROMIUM:-}" ] && [ ! -x /usr/bin/chromium ]; then
    cyclide_ensure_packages chromium
  fi
}
