// The curve session's panel: the tolerance slider (log scale), degree, error measure,
// algorithm, closed and control-polygon toggles, and the readout of the last fit.
const $ = (id) => document.getElementById(id);

// The slider's 0 ... 1000 spans tolerances of 0.1 ... 100 pixels, evenly in log scale.
const LOG_LOW = -1, LOG_HIGH = 2, STEPS = 1000;
export const sliderToTolerance = (v) => 10 ** (LOG_LOW + ((LOG_HIGH - LOG_LOW) * v) / STEPS);
export const toleranceToSlider = (t) => Math.round((STEPS * (Math.log10(t) - LOG_LOW)) / (LOG_HIGH - LOG_LOW));

const px = (x) => (x >= 10 ? x.toFixed(1) : x >= 1 ? x.toFixed(2) : x.toPrecision(2));

export class CurvePanel {
  bind(session, view) {
    this.session = session;
    const slider = $('curve-tolerance');
    // Every input event asks for a fit; the queue keeps only the latest one waiting.
    slider.addEventListener('input', () => {
      const tolerance = sliderToTolerance(Number(slider.value));
      this.showTolerance(tolerance);
      session.setSettings({ tolerance });
    });
    $('curve-degree').addEventListener('change', (e) => session.setSettings({ degree: Number(e.target.value) }));
    $('curve-error').addEventListener('change', (e) => session.setSettings({ error: e.target.value }));
    $('curve-algorithm').addEventListener('change', (e) => session.setSettings({ algorithm: e.target.value }));
    $('curve-closed').addEventListener('change', (e) => session.setSettings({ closed: e.target.checked }));
    $('curve-polygon').addEventListener('change', (e) => view.setPolygon(e.target.checked));
    $('curve-clear').addEventListener('click', () => session.clear());
    this.settings(session.settings);
  }

  showTolerance(t) {
    $('curve-tolerance-value').textContent = `${px(t)} px`;
  }

  // The controls show `s` (after a refusal: the settings the server kept).
  settings(s) {
    $('curve-tolerance').value = String(toleranceToSlider(s.tolerance));
    this.showTolerance(s.tolerance);
    $('curve-degree').value = String(s.degree);
    $('curve-error').value = s.error;
    $('curve-algorithm').value = s.algorithm;
    $('curve-closed').checked = s.closed;
  }

  info(message) {
    $('curve-details').textContent = `at most ${message.limits.max_points} points per stroke`;
  }

  // header: the last `curve` answer; total: its round trip in ms.
  fit(h, total) {
    if (h.points === 0) {
      $('curve-readout').textContent = 'no stroke yet';
      $('curve-details').textContent = '';
      return;
    }
    $('curve-readout').textContent = `${h.knots} knots, max error ${px(h.max_error)} px, ${h.timings.fit_ms.toFixed(1)} ms`;
    $('curve-readout').classList.toggle('missed', !h.within_bound);
    $('curve-details').textContent = `RMS error ${px(h.rms_error)} px; ${h.error} bound ${px(h.tolerance)} px ` +
      `${h.within_bound ? 'met' : 'not met (the best fit found)'}; ${h.points} points, degree ${h.degree}` +
      `${h.closed ? ', closed' : ''}, ${h.control_points} control points` +
      (Number.isFinite(total) ? `; round trip ${total.toFixed(1)} ms` : '');
  }
}
