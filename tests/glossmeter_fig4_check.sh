#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The table of Fig. 4's glossmeter readings in docs/guide/gloss-bridge.md is the output of
# `pgloss glossmeter --fig4 --markdown`, regenerated whole: fails (with the diff) when it is not.
set -euo pipefail
cli=$1 page=$2
want=$(sed -n '/<!-- glossmeter-fig4:begin -->/,/<!-- glossmeter-fig4:end -->/p' "$page" | sed '1d;$d')
got=$("$cli" glossmeter --fig4 --markdown)
if [[ "$want" != "$got" ]]; then
  diff <(echo "$want") <(echo "$got") || true
  echo "$page's glossmeter table is stale: replace it with the output of: pgloss glossmeter --fig4 --markdown" >&2
  exit 1
fi
echo "$page's glossmeter table is up to date"
