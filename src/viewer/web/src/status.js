// The status line of the page and the progress of long work (a basis being computed), also in
// the middle of the view until the first picture: shared by every session kind.

const $ = (id) => document.getElementById(id);
const ERROR_HOLD_MS = 5000; // an error stays readable for a while, even while edits go on

export class StatusLine {
  constructor() {
    this.errorUntil = 0;
  }

  status(text) {
    if (!$('waiting').hidden) $('waiting-text').textContent = text;
    if (performance.now() < this.errorUntil) return;
    const line = $('status');
    line.textContent = text;
    line.classList.remove('error');
  }

  error(text) {
    if (!$('waiting').hidden) $('waiting-text').textContent = text;
    const line = $('status');
    line.textContent = text;
    line.classList.add('error');
    this.errorUntil = performance.now() + ERROR_HOLD_MS;
    $('progress-row').hidden = true;
  }

  // The basis being computed (before the first field: also in the middle of the view) or
  // the full solver at work.
  progress(stage, fraction) {
    const f = Math.max(0, Math.min(1, fraction || 0));
    const text = `${stage} ${Math.round(100 * f)}%`;
    $('progress-row').hidden = false;
    $('progress').value = f;
    $('progress-stage').textContent = text;
    if (!$('waiting').hidden) {
      $('waiting-text').textContent = text;
      $('waiting-progress').hidden = false;
      $('waiting-progress').value = f;
    }
  }

  progressDone() {
    $('progress-row').hidden = true;
  }

  // The session's first picture is on screen: the view no longer waits.
  shown() {
    this.progressDone();
    $('waiting').hidden = true;
  }
}
