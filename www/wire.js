// The frame as it crosses from a worker (the core's wire form) read back into the page's parts.

/** A value in the core's wire form (rime_core::wire) read back: its JSON with each
 * `{"$f64": [at, len]}` / `{"$u8": [at, len]}` as a view into `numbers` / `codes`. */
export function readWire(json, numbers, codes) {
  return JSON.parse(json, (_, v) => {
    if (v === null || typeof v !== 'object' || Array.isArray(v)) return v;
    if (v.$f64) return numbers.subarray(v.$f64[0], v.$f64[0] + v.$f64[1]);
    return v.$u8 ? codes.subarray(v.$u8[0], v.$u8[0] + v.$u8[1]) : v;
  });
}

/** The frame (the core frame's serde form and the page's keys, snake_case) as the page's parts. */
export function decode(msg, page) {
  const j = readWire(msg.json, msg.numbers, msg.codes);
  const m = j.map;
  const note = m && m.auto ? m.auto.note : null;
  const mapError = () => (j.errors.find((e) => e.part === 'stick map') || { message: '' }).message;
  const members = j.family;
  const res = {
    accuracy: page.view.accuracy,
    values: j.values,
    g: j.g,
    eps: j.curve ? j.curve.eps : null,
    status: j.curve ? j.curve.status : null,
    gaps: j.curve ? j.curve.failed : 0,
    clean: j.clean ? j.clean.eps : null,
    family: members.length ? {
      path: j.sweep.path, sym: j.sweep.symbol, unit: j.sweep.unit, values: members.map((x) => x.value),
      isScene: members.map((x) => x.is_scene), curves: members.map((x) => (x.curve ? x.curve.eps : null)),
    } : null,
    crit: j.markers,
    warnings: j.warnings.map((w) => w.text),
    warningDetails: j.warnings,
    friction: j.values.friction === true,
    map: m && m.map ? { n: j.map_n, max: m.max, note, codes: m.map.class, epsT: m.map.eps_t, epsN: m.map.eps_n, g: m.map.g } : null,
    mapFailed: m && !m.map ? { n: j.map_n, max: m.max, note, error: mapError() } : null,
    mapNote: note,
    tidal: j.tidal.error ? null : j.tidal,
    overlays: j.overlays,
    figures: j.figures,
    errors: j.tidal.error ? [...j.errors, { part: 'tidal', message: j.tidal.error }] : j.errors,
  };
  // The records (UTF-8 JSON from the worker) are read when a download first asks for them.
  let records = null;
  Object.defineProperty(res, 'records', {
    enumerable: true,
    get() { records ||= JSON.parse(new TextDecoder().decode(msg.records)); return records; },
  });
  return res;
}
