#!/usr/bin/env bash
# Creates the shared store of a class or a study on a Debian PostgreSQL server (run it on the server):
# a login role and a database it owns, then prints the --store URL for the desktops.
#   scripts/create_class_store.sh [DATABASE [ROLE]]     # default: skillcoach coach
# It runs psql as the postgres user (root or sudo needed), or with the PG* environment variables when
# PGHOST is set. The desktops' records are created by SkillCoach itself at the first start.
# To let the desktops in: listen_addresses = '*' in /etc/postgresql/15/main/postgresql.conf and a line
#   hostssl DATABASE ROLE 192.168.1.0/24 scram-sha-256
# in pg_hba.conf (your class's network), then `systemctl reload postgresql`.
set -euo pipefail
database="${1:-skillcoach}"
role="${2:-coach}"
[[ "$database" =~ ^[a-z_][a-z0-9_]*$ && "$role" =~ ^[a-z_][a-z0-9_]*$ ]] ||
  { echo "create_class_store.sh: DATABASE and ROLE: lower-case letters, digits and _" >&2; exit 2; }
password="$(head -c 18 /dev/urandom | base64 | tr '+/' '-_')"
psql_cmd=(psql -X -q -v ON_ERROR_STOP=1 -d postgres)
if [ -z "${PGHOST:-}" ]; then
  if [ "$(id -u)" -eq 0 ]; then psql_cmd=(runuser -u postgres -- "${psql_cmd[@]}"); else psql_cmd=(sudo -u postgres "${psql_cmd[@]}"); fi
fi
"${psql_cmd[@]}" <<SQL
CREATE ROLE $role LOGIN PASSWORD '$password';
CREATE DATABASE $database OWNER $role ENCODING 'UTF8' TEMPLATE template0;
REVOKE ALL ON DATABASE $database FROM PUBLIC;
SQL
echo "created database $database owned by role $role; the desktops use:"
echo "  --store postgresql://$role:$password@$(hostname -f 2>/dev/null || hostname)/$database"
