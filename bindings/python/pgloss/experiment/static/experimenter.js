// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The experimenter's view: who has run, how far, export links (all need the page's token).
"use strict";

const token = new URLSearchParams(location.search).get("token") || "";
const withToken = (path) => `${path}?token=${encodeURIComponent(token)}`;

function cell(text, cls) {
  const td = document.createElement("td");
  td.textContent = text;
  if (cls) td.className = cls;
  return td;
}

async function refresh() {
  const r = await fetch(withToken("/api/progress"), { cache: "no-store" });
  if (!r.ok) return;
  const rows = (await r.json()).subjects;
  const body = document.querySelector("#progress tbody");
  body.replaceChildren(...rows.map((s) => {
    const tr = document.createElement("tr");
    if (s.responses === s.trials) tr.className = "complete";
    tr.append(cell(s.subject), cell(s.procedure), cell(String(s.responses), "num"), cell(String(s.trials), "num"),
              cell(String(s.sittings), "num"), cell(String(s.seed), "num"), cell(s.created_at),
              cell(s.last_response_at || "–"));
    const td = document.createElement("td");
    if (s.procedure === "pairs" && s.responses > 0) {
      const a = document.createElement("a");
      a.href = withToken(`/export/pairs/${encodeURIComponent(s.subject)}.csv`);
      a.textContent = `${s.subject}.csv`;
      td.append(a);
    }
    tr.append(td);
    return tr;
  }));
  document.body.dataset.loaded = "1";
}

for (const what of ["magnitude", "responses", "stimuli"]) {
  document.getElementById(`export-${what}`).href = withToken(`/export/${what}.csv`);
}
refresh();
setInterval(refresh, 5000);
