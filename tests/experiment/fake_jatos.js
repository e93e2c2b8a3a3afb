// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// A stand-in for JATOS's jatos.js (3.x API: onLoad, workerId, urlQueryParameters,
// appendResultData, endStudy, endStudyAndRedirect) that keeps what the study sends in the page,
// for test_jspsych.py to collect and pack as a JATOS results archive.
"use strict";
window.jatos = {
  version: "3.10.4 (test stand-in)", workerId: 77, studyResultId: 5, componentResultId: 9, urlQueryParameters: {},
  data: [],
  onLoad(callback) { setTimeout(callback, 0); },
  appendResultData(text) { this.data.push(String(text)); return Promise.resolve(); },
  submitResultData(text) { this.data = [String(text)]; return Promise.resolve(); },
  endStudy(successful, message) { this.ended = { successful, message }; return Promise.resolve(); },
  endStudyAndRedirect(url, successful, message) { this.ended = { successful, message, url }; },
};
