// SMPL Olympics match viewer: reads a scene track (docs/viewer.md, "Scene data") and draws it
// with three.js. Sources: a track embedded by `olympics-server view --export`, a file served by
// `olympics-server view` (scene.bin), or a live match from `serve --view-port` (server-sent
// events, one record per message). URL parameters: frame=N (start paused there), camera=
// broadcast|top|free|followK, slot=K (the chart's slot), speed=X, live=MATCH_ID.
(function () {
  'use strict';
  const THREE = window.THREE;
  const params = new URLSearchParams(location.search);
  const $ = (id) => document.getElementById(id);

  // ---------------------------------------------------------------- the track
  // Records: type (1 byte), length (u32 LE), payload.
  class Track {
    constructor() {
      this.header = null;
      this.frames = [];   // {tick, view: DataView of the payload}
      this.events = [];   // {tick, events, score}, in tick order
      this.result = null;
      this.changed = 0;   // counts additions, so views know when to redraw
    }
    addRecords(bytes) {
      const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
      let at = 0;
      while (at + 5 <= bytes.length) {
        const type = String.fromCharCode(bytes[at]);
        const size = dv.getUint32(at + 1, true);
        const payload = bytes.subarray(at + 5, at + 5 + size);
        at += 5 + size;
        this.addRecord(type, payload);
      }
    }
    addRecord(type, payload) {
      const text = () => new TextDecoder().decode(payload);
      if (type === 'H') {
        this.header = JSON.parse(text());
        this.bodyCount = this.header.body_count;
        this.teamCount = this.header.team_count;
        this.termCount = this.header.reward_terms.length;
        this.slots = this.header.slots;
        this.quantum = this.header.position_quantum_m;
      } else if (type === 'F') {
        const view = new DataView(payload.buffer, payload.byteOffset, payload.byteLength);
        this.frames.push({ tick: view.getUint32(0, true), view });
      } else if (type === 'E') {
        this.events.push(JSON.parse(text()));
      } else if (type === 'R') {
        this.result = JSON.parse(text());
      }
      this.changed++;
    }
    // Position and quaternion (w, x, y, z) of `body` in frame `f`.
    pose(f, body, out) {
      const v = this.frames[f].view, at = 4 + body * 14, q = this.quantum;
      out[0] = v.getInt16(at, true) * q;
      out[1] = v.getInt16(at + 2, true) * q;
      out[2] = v.getInt16(at + 4, true) * q;
      for (let i = 0; i < 4; i++) out[3 + i] = v.getInt16(at + 6 + 2 * i, true) / 32767;
      return out;
    }
    scores(f) {
      const v = this.frames[f].view, at = 4 + this.bodyCount * 14, out = [];
      for (let t = 0; t < this.teamCount; t++) out.push(v.getFloat32(at + 4 * t, true));
      return out;
    }
    // The reward then each term of `slot` in frame `f`.
    rewards(f, slot) {
      const v = this.frames[f].view, per = 1 + this.termCount;
      const at = 4 + this.bodyCount * 14 + 4 * this.teamCount + 4 * slot * per, out = [];
      for (let k = 0; k < per; k++) out.push(v.getFloat32(at + 4 * k, true));
      return out;
    }
    // The newest events record at or before `tick`, and the calls made up to it.
    eventsUpTo(tick) {
      let last = null;
      const calls = [];
      for (const e of this.events) {
        if (e.tick > tick) break;
        if (e.score !== undefined) last = e;
        for (const c of e.events) calls.push(c);
      }
      return { score: last ? last.score : null, calls };
    }
    seconds(f) { return this.frames[f].tick / this.header.control_hz; }
  }

  function base64Bytes(text) {
    const raw = atob(text.trim());
    const out = new Uint8Array(raw.length);
    for (let i = 0; i < raw.length; i++) out[i] = raw.charCodeAt(i);
    return out;
  }

  // ---------------------------------------------------------------- drawing
  const TEAM_COLORS = ['#d63a2f', '#2f62d6', '#2fa84f', '#c9a227'];
  const ROLE_COLORS = { equipment: '#26282c', ball: '#e4f04a', arena: '#8c8c8c', net: '#eeeeee',
                        table: '#1d6b45' };

  function geometryOf(shape) {
    const s = shape.size;
    let g;
    if (shape.type === 'box') g = new THREE.BoxGeometry(2 * s[0], 2 * s[1], 2 * s[2]);
    else if (shape.type === 'sphere') g = new THREE.SphereGeometry(s[0], 20, 14);
    else if (shape.type === 'capsule') g = new THREE.CapsuleGeometry(s[0], 2 * s[1], 6, 14);
    else if (shape.type === 'cylinder') g = new THREE.CylinderGeometry(s[0], s[0], 2 * s[1], 18);
    else return null;
    if (shape.type === 'capsule' || shape.type === 'cylinder') g.rotateX(Math.PI / 2);  // y -> z
    return g;
  }

  class Stage {
    constructor(canvas, track) {
      this.track = track;
      const h = track.header, scene = h.scene;
      this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true,
                                                preserveDrawingBuffer: true });
      this.scene = new THREE.Scene();
      this.scene.background = new THREE.Color('#20242b');
      this.camera = new THREE.PerspectiveCamera(45, 1, 0.05, 400);
      this.camera.up.set(0, 0, 1);
      this.scene.add(new THREE.HemisphereLight('#ffffff', '#404040', 1.6));
      const sun = new THREE.DirectionalLight('#ffffff', 1.6);
      sun.position.set(-6, -10, 14);
      this.scene.add(sun);
      const ground = scene.ground || { half: [20, 20], color: '#5d7d4a' };
      const floor = new THREE.Mesh(new THREE.PlaneGeometry(2 * ground.half[0], 2 * ground.half[1]),
                                   new THREE.MeshLambertMaterial({ color: ground.color }));
      this.scene.add(floor);
      if (scene.lines && scene.lines.length) {
        const pts = [];
        for (const l of scene.lines) pts.push(...l.a, ...l.b);
        const g = new THREE.BufferGeometry();
        g.setAttribute('position', new THREE.Float32BufferAttribute(pts, 3));
        this.scene.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: '#ffffff' })));
      }
      const teams = scene.teams || [];
      this.bodies = (scene.bodies || []).map(() => {
        const group = new THREE.Group();
        this.scene.add(group);
        return group;
      });
      this.pose = new Float32Array(7);
      this.roots = [];  // per slot: its first body (the pelvis)
      (scene.bodies || []).forEach((b, i) => {
        if (b.slot >= 0 && this.roots[b.slot] === undefined) this.roots[b.slot] = i;
      });
      for (const shape of scene.shapes || []) {
        const g = geometryOf(shape);
        if (!g) continue;
        const body = shape.body >= 0 ? scene.bodies[shape.body] : null;
        let color = new THREE.Color(shape.color || ROLE_COLORS[shape.role] || '#9a9a9a');
        if (!shape.color && body && body.slot >= 0 && shape.role !== 'ball') {
          // A player's body in its team's colour, what it holds in a darker shade of it.
          color = new THREE.Color(TEAM_COLORS[(teams[body.slot] || 0) % TEAM_COLORS.length]);
          if (shape.role === 'equipment') color.multiplyScalar(0.45);
        }
        const mesh = new THREE.Mesh(g, new THREE.MeshLambertMaterial({ color }));
        mesh.position.set(...shape.pos);
        mesh.quaternion.set(shape.quat[1], shape.quat[2], shape.quat[3], shape.quat[0]);
        (shape.body >= 0 ? this.bodies[shape.body] : this.scene).add(mesh);
      }
      this.extent = this.playExtent(scene);
      this.controls = new THREE.OrbitControls(this.camera, canvas);
      this.controls.enabled = false;
      this.cameraMode = '';
    }
    // Half extents (x, y) of where play happens: the markings, the static arena and the players'
    // start, so that the cameras frame a table as well as a court.
    playExtent(scene) {
      let hx = 1, hy = 1;
      const grow = (x, y) => { hx = Math.max(hx, Math.abs(x)); hy = Math.max(hy, Math.abs(y)); };
      for (const l of scene.lines || []) { grow(l.a[0], l.a[1]); grow(l.b[0], l.b[1]); }
      for (const s of scene.shapes || [])
        if (s.body < 0 && s.type !== 'box') grow(s.pos[0], s.pos[1]);
        else if (s.body < 0) grow(Math.abs(s.pos[0]) + s.size[0], Math.abs(s.pos[1]) + s.size[1]);
      if (this.track.frames.length)
        for (const b of this.roots) { const p = this.track.pose(0, b, this.pose); grow(p[0], p[1]); }
      return [hx + 0.5, hy + 0.5];
    }
    resize(width, height) {
      this.renderer.setSize(width, height, false);
      this.camera.aspect = width / height;
      this.camera.updateProjectionMatrix();
    }
    setCamera(mode) {
      if (mode === this.cameraMode) return;
      this.cameraMode = mode;
      this.controls.enabled = mode === 'free';
      const [hx, hy] = this.extent;
      const tanV = Math.tan(this.camera.fov * Math.PI / 360), tanH = tanV * this.camera.aspect;
      if (mode === 'top') {
        this.camera.up.set(0, 1, 0);
        this.camera.position.set(0, 0, 1.1 * Math.max(hx / tanH, hy / tanV) + 2);
        this.camera.lookAt(0, 0, 0);
      } else {
        this.camera.up.set(0, 0, 1);
        if (mode === 'broadcast' || mode === 'free') {
          // From the side, 30 degrees up, far enough that the play area's length fits.
          const d = 1.1 * hx / tanH + hy;
          this.camera.position.set(0, -d * 0.87, d * 0.5 + 0.8);
          this.controls.target.set(0, 0, 0.8);
          this.camera.lookAt(0, 0, 0.8);
        }
      }
      this.controls.update();
    }
    show(f) {
      const t = this.track;
      for (let b = 0; b < this.bodies.length; b++) {
        const p = t.pose(f, b, this.pose);
        this.bodies[b].position.set(p[0], p[1], p[2]);
        this.bodies[b].quaternion.set(p[4], p[5], p[6], p[3]);
      }
      const follow = /^follow(\d+)$/.exec(this.cameraMode);
      if (follow && this.roots[+follow[1]] !== undefined) {
        const r = this.bodies[this.roots[+follow[1]]].position;
        this.camera.position.set(r.x - 3.5, r.y - 3.5, r.z + 1.8);
        this.camera.lookAt(r.x, r.y, r.z);
      }
      if (this.controls.enabled) this.controls.update();
      this.renderer.render(this.scene, this.camera);
    }
    // Where each slot's root is on the canvas, in CSS pixels (the browser tests read this).
    projectedRoots() {
      const canvas = this.renderer.domElement, out = [];
      this.roots.forEach((b, slot) => {
        const v = this.bodies[b].position.clone().project(this.camera);
        out.push({ slot, x: (v.x + 1) / 2 * canvas.clientWidth,
                   y: (1 - v.y) / 2 * canvas.clientHeight, visible: Math.abs(v.z) < 1 });
      });
      return out;
    }
  }

  // ---------------------------------------------------------------- overlays
  // The sport's own score: its text when it has one (tennis: "6-4 2-1 30-15"), else its fields.
  function scoreText(score) {
    if (score === null || score === undefined) return '';
    if (typeof score !== 'object') return String(score);
    if (typeof score.text === 'string') return score.text;
    return Object.entries(score).filter(([, v]) => !(Array.isArray(v) && !v.length))
      .map(([k, v]) => `${k}: ${JSON.stringify(v)}`).join('\n');
  }

  function drawScoreboard(track, f) {
    const h = track.header, scores = track.scores(f), agents = h.agents || [];
    const teams = (h.scene.teams || []);
    const names = [];
    for (let t = 0; t < h.team_count; t++)
      names.push(agents.filter((_, s) => (teams[s] || 0) === t).join(' & ') || `team ${t}`);
    const ev = track.eventsUpTo(track.frames[f].tick);
    const atEnd = track.result && f === track.frames.length - 1;
    let html = `<div>${h.sport} ${h.mode} &middot; ${h.match_id || ''}</div><div class="score">`;
    html += scores.map((s, t) => `<span class="team${t}">${names[t]} ${+s.toFixed(2)}</span>`)
      .join(' &ndash; ') + '</div>';
    html += `<div class="detail">${scoreText(ev.score)}</div>`;
    if (atEnd) {
      const r = track.result;
      html += `<div class="final">final: ${r.reason}, ` +
              (r.winner_team >= 0 ? `won by ${names[r.winner_team]}` : 'no winner') + '</div>';
    }
    $('scoreboard').innerHTML = html;
    const calls = ev.calls.slice(-4).map((c) =>
      `${(c.t !== undefined ? c.t.toFixed(1) + ' s ' : '')}${c.call}` +
      (c.slot !== undefined ? ` (slot ${c.slot})` : ''));
    $('calls').innerHTML = calls.join('<br>');
    return { scores, names, final: atEnd ? track.result : null };
  }

  const TERM_COLORS = ['#ffffff', '#ff8a65', '#4fc3f7', '#aed581', '#ffd54f', '#ba68c8', '#4db6ac',
                       '#f06292', '#90a4ae'];

  function drawChart(track, f, slot) {
    const canvas = $('chart'), g = canvas.getContext('2d');
    const W = canvas.width, H = canvas.height, window = 10 * track.header.control_hz;
    const from = Math.max(0, f - window);
    const series = [];
    for (let i = from; i <= f; i++) series.push(track.rewards(i, slot));
    let lo = 0, hi = 0;
    for (const r of series) for (const v of r) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    if (hi - lo < 1e-6) hi = lo + 1;
    g.clearRect(0, 0, W, H);
    g.strokeStyle = '#555';
    const y = (v) => H - 4 - (v - lo) / (hi - lo) * (H - 8);
    g.beginPath(); g.moveTo(0, y(0)); g.lineTo(W, y(0)); g.stroke();
    const per = 1 + track.termCount;
    for (let k = 0; k < per; k++) {
      g.strokeStyle = TERM_COLORS[k % TERM_COLORS.length];
      g.lineWidth = k === 0 ? 2 : 1;
      g.beginPath();
      series.forEach((r, i) => {
        const x = (i + (window - (f - from))) / window * W;
        if (i === 0) g.moveTo(x, y(r[k])); else g.lineTo(x, y(r[k]));
      });
      g.stroke();
    }
    if (!drawChart.legend || drawChart.legend !== track.termCount) {
      drawChart.legend = track.termCount;
      $('chart-legend').innerHTML = ['reward', ...track.header.reward_terms].map((n, k) =>
        `<span style="color:${TERM_COLORS[k % TERM_COLORS.length]}">${n}</span>`).join('');
    }
  }

  // ---------------------------------------------------------------- the player
  class Player {
    constructor(track, live) {
      this.track = track;
      this.live = live;
      this.stage = new Stage($('view'), track);
      this.frame = 0;
      this.playing = !params.has('frame') && !live;
      this.following = live;  // live: stay on the newest frame until the user scrubs
      this.speed = +(params.get('speed') || 1);
      this.clock = 0;
      this.chartSlot = +(params.get('slot') || 0);
      this.setupControls();
      this.resize();
      window.addEventListener('resize', () => this.resize());
      if (params.has('frame')) this.frame = Math.min(+params.get('frame'), track.frames.length - 1);
      this.seenChange = -1;
      this.last = performance.now();
      requestAnimationFrame((t) => this.loop(t));
    }
    setupControls() {
      const cam = $('camera');
      for (let s = 0; s < this.track.slots; s++) {
        cam.add(new Option(`follow slot ${s}`, `follow${s}`));
        $('chart-slot').add(new Option(`slot ${s}` +
          (this.track.header.agents ? ` (${this.track.header.agents[s]})` : ''), String(s)));
      }
      cam.value = params.get('camera') || 'broadcast';
      $('chart-slot').value = String(this.chartSlot);
      $('chart-slot').onchange = () => { this.chartSlot = +$('chart-slot').value; this.dirty = true; };
      $('speed').value = String(this.speed);
      $('speed').onchange = () => { this.speed = +$('speed').value; };
      $('play').onclick = () => this.toggle();
      $('timeline').oninput = () => {
        this.frame = +$('timeline').value;
        this.following = this.live && this.frame === this.track.frames.length - 1;
        this.dirty = true;
      };
      cam.onchange = () => { this.dirty = true; };
      window.addEventListener('keydown', (e) => {
        if (e.code === 'Space') { this.toggle(); e.preventDefault(); }
      });
    }
    toggle() {
      this.playing = !this.playing;
      if (this.playing && this.frame >= this.track.frames.length - 1 && !this.live) this.frame = 0;
    }
    resize() {
      const c = $('view');
      this.stage.resize(c.clientWidth, c.clientHeight);
      this.stage.cameraMode = '';
      this.dirty = true;
    }
    loop(now) {
      const t = this.track, n = t.frames.length;
      const dt = Math.min(0.25, (now - this.last) / 1000);
      this.last = now;
      if (n > 0) {
        if (this.following) {
          this.frame = n - 1;
        } else if (this.playing) {
          this.clock += dt * this.speed * t.header.control_hz;
          const step = Math.floor(this.clock);
          this.clock -= step;
          if (step > 0) {
            this.frame = Math.min(n - 1, this.frame + step);
            if (this.frame === n - 1 && !this.live) this.playing = false;
          }
        }
        if (this.frame !== this.shown || this.dirty || t.changed !== this.seenChange)
          this.render();
      }
      requestAnimationFrame((x) => this.loop(x));
    }
    render() {
      const t = this.track, f = this.frame;
      this.shown = f;
      this.dirty = false;
      this.seenChange = t.changed;
      this.stage.setCamera($('camera').value);
      this.stage.show(f);
      $('timeline').max = String(t.frames.length - 1);
      $('timeline').value = String(f);
      $('clock').textContent = `${t.seconds(f).toFixed(2)} s / ` +
        `${t.seconds(t.frames.length - 1).toFixed(2)} s (tick ${t.frames[f].tick})`;
      $('play').innerHTML = this.playing ? '&#10074;&#10074;' : '&#9654;';
      const board = drawScoreboard(t, f);
      drawChart(t, f, this.chartSlot);
      $('probe').textContent = JSON.stringify({
        frame: f, frames: t.frames.length, tick: t.frames[f].tick, camera: this.stage.cameraMode,
        roots: this.stage.projectedRoots(), scores: board.scores, final: board.final,
        live: this.live, ended: !!t.result,
      });
    }
  }

  // ---------------------------------------------------------------- sources
  function message(text) {
    $('message').hidden = !text;
    $('message').textContent = text || '';
  }

  function startWith(track, live) {
    if (!track.header) return message('the scene track has no header');
    if (!track.frames.length && !live) return message('the scene track has no frames');
    message('');
    window.viewer = new Player(track, live);
  }

  function watchLive(matchId) {
    const track = new Track();
    let started = false;
    message(`waiting for match ${matchId}...`);
    const source = new EventSource(`api/live/${encodeURIComponent(matchId)}`);
    source.onmessage = (e) => {
      track.addRecords(base64Bytes(e.data));
      if (!started && track.header && track.frames.length) {
        started = true;
        startWith(track, true);
      }
    };
    source.addEventListener('end', () => source.close());
    source.onerror = () => { if (!started) message(`no live match ${matchId} on this server`); };
  }

  async function listMatches() {
    const box = $('matches');
    box.hidden = false;
    $('controls').hidden = true;
    $('chart-panel').hidden = true;
    const refresh = async () => {
      const list = await (await fetch('api/matches')).json();
      box.innerHTML = '<b>Matches on this server</b> (click one to watch it live)<br>' +
        (list.length ? list.map((m) => `<a href="?live=${encodeURIComponent(m.match_id)}">` +
          `${m.match_id}</a> ${m.sport} ${m.mode}, tick ${m.tick}${m.ended ? ' (ended)' : ''}`)
          .join('<br>') : 'none yet');
      $('probe').textContent = JSON.stringify({ matches: list });
    };
    await refresh();
    setInterval(refresh, 1000);
  }

  async function main() {
    const embedded = document.getElementById('scene-data');
    try {
      if (embedded) {
        const track = new Track();
        track.addRecords(window.fzstd.decompress(base64Bytes(embedded.textContent)));
        return startWith(track, false);
      }
      if (params.has('live')) return watchLive(params.get('live'));
      const mode = await (await fetch('api/mode')).json();
      if (mode.mode === 'live') return listMatches();
      const bytes = new Uint8Array(await (await fetch(mode.scene)).arrayBuffer());
      const track = new Track();
      track.addRecords(window.fzstd.decompress(bytes));
      startWith(track, false);
    } catch (e) {
      message(`cannot show this match: ${e.message}`);
      throw e;
    }
  }
  main();
})();
