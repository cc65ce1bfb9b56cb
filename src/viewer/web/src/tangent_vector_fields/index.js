// The field sessions' side of the page (Chapters 1 and 2): both kinds, "vector_field" and
// "n_field", mount the same editor, which follows the design the server reports (`info.n`).
import { Editor } from './editor.js';
import { Tools } from './tools.js';
import { Panel } from './ui.js';
import { installHook } from './hook.js';
import panelHtml from './panel.html';

export const fieldKind = {
  binaryAnswers: ['add', 'change', 'remove', 'clear', 'load', 'set_omega', 'set_basis_size', 'set_solver',
    'set_display', 'set_n'],
  mount({ connection, viewer, latency, line }) {
    document.getElementById('kind-title').textContent = 'Field editor';
    document.title = 'tvf field editor';
    document.getElementById('kind-panel').innerHTML = panelHtml;
    document.getElementById('help').textContent = 'Left-drag: orbit (or place with a tool) · right-drag: pan · ' +
      'wheel: zoom · Delete: remove the selected constraint · Esc: deselect';
    const panel = new Panel(line);
    const editor = new Editor(connection, viewer, latency, line, panel);
    const tools = new Tools(editor, document.getElementById('view'));
    panel.bind(editor, tools);
    installHook({ connection, viewer, editor, tools });
    return editor;
  },
};
