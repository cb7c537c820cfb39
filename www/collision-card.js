// The collision card's requests and answers: one collision of the drawn scene at `app.collisionG`,
// integrated in the collision worker, and the card marked busy while it shows another one.
import { $, markBusy } from './dom.js';
import { app } from './state.js';

/** One collision of the drawn scene at `app.collisionG` (integrated in the collision worker). */
let replayed = '';
let collisionShown = ''; // the scene, level and speed of the collision on the card
/** What names one collision: its scene, level and speed. */
const collisionOf = (scene, accuracy, g) => `${scene}|${accuracy}|${g}`;
const collisionKey = () => (app.drawn ? collisionOf(app.drawn.scene, app.drawn.view.accuracy, app.collisionG) : '');
/** The collision card says it shows another scene's collision (or level's, or speed's) than the one
 *  asked for, from the edit until the replay arrives (the replay follows once the edits pause). */
export function markCollision() {
  markBusy($('collision-card'), collisionShown !== collisionOf(app.wantScene, app.view.accuracy, app.collisionG));
}
export function replayCollision(g) {
  if (g !== undefined) app.collisionG = g;
  if (!app.drawn || !app.collisionView) return;
  // A new frame of the same scene at the same level (a zoom, an axis) does not replay it.
  const key = collisionKey();
  if (g === undefined && key === replayed) return;
  replayed = key;
  // Integrated in the collision worker (issue 22: it ran here, on the page's thread).
  app.collider.request(app.drawn.scene, app.collisionG, 300, app.drawn.view.accuracy, { requested: g !== undefined });
}

/** The collision worker's answer to the newest request. */
export function onCollision(msg, req) {
  collisionShown = req ? collisionOf(req.scene, req.accuracy, req.g) : '';
  markCollision();
  if (msg.error) {
    console.error(`rime: collision: ${msg.error}`);
    app.collisionView.fail(msg.error);
    return;
  }
  const d = JSON.parse(msg.json);
  app.collisionView.show(d, req.requested);
  window.rimeState.collision = {
    g: d.g, eps_n: d.eps_n, t_c: d.t_c, status: d.status, closure: d.ledger.closure,
    n: d.t.length, dynamic: d.dynamic !== null, animating: app.collisionView.animating,
    reduced: app.collisionView.reduced, ms: msg.ms,
  };
}
