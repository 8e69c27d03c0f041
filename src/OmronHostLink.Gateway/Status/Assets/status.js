// The gateway's status page: four views, each fed by a stream of server-sent events from the gateway while it is
// shown (nothing is asked for the others). Plain script, no build step, nothing loaded from elsewhere.
'use strict';

(() => {
  const views = {};
  let current = null;
  let clockOffset = 0; // the gateway's clock less this browser's, from each document's "now"

  // ---- helpers ----------------------------------------------------------------------------------------------------

  function el(tag, attributes, ...children) {
    const node = document.createElement(tag);
    for (const [name, value] of Object.entries(attributes || {})) {
      if (value === null || value === undefined || value === false) continue;
      if (name === 'class') node.className = value;
      else if (name === 'text') node.textContent = value;
      else node.setAttribute(name, value === true ? '' : value);
    }
    for (const child of children) {
      if (child === null || child === undefined) continue;
      node.append(child instanceof Node ? child : document.createTextNode(String(child)));
    }
    return node;
  }

  function clockTime(iso) {
    if (!iso) return '—';
    const d = new Date(iso);
    return d.toLocaleTimeString([], { hour12: false }) + '.' + String(d.getMilliseconds()).padStart(3, '0');
  }

  function dateTime(iso) {
    if (!iso) return '—';
    const d = new Date(iso);
    const today = new Date();
    return d.toDateString() === today.toDateString() ? clockTime(iso) : d.toLocaleString([], { hour12: false });
  }

  function age(iso) {
    if (!iso) return '—';
    const ms = Date.now() + clockOffset - new Date(iso).getTime();
    if (ms < 1000) return `${Math.max(0, ms).toFixed(0)} ms`;
    const s = ms / 1000;
    if (s < 60) return `${s.toFixed(1)} s`;
    if (s < 3600) return `${Math.floor(s / 60)} min ${Math.floor(s % 60)} s`;
    return `${Math.floor(s / 3600)} h ${Math.floor((s % 3600) / 60)} min`;
  }

  function ms(value) {
    return value === null || value === undefined ? '—' : `${Number(value).toFixed(value < 10 ? 2 : 1)} ms`;
  }

  function interval(value) {
    return value >= 1000 && value % 1000 === 0 ? `${value / 1000} s` : `${value} ms`;
  }

  function number(value, digits) {
    return value === null || value === undefined ? '—' : Number(value).toFixed(digits);
  }

  function took(document) {
    if (document && document.now) clockOffset = new Date(document.now).getTime() - Date.now();
  }

  function badge(state) {
    return el('span', { class: `badge state-${state}`, text: state });
  }

  function failures(byKind) {
    const kinds = Object.entries(byKind || {});
    return kinds.length === 0 ? 'none' : kinds.map(([kind, count]) => `${kind} ${count}`).join(', ');
  }

  // One stream per shown view; the browser reconnects a dropped one by itself.
  function stream(url, handlers) {
    const source = new EventSource(url);
    const status = document.getElementById('connection');
    source.onopen = () => { status.textContent = 'live'; status.className = 'connection live'; };
    source.onerror = () => { status.textContent = 'reconnecting…'; status.className = 'connection lost'; };
    for (const [event, handle] of Object.entries(handlers)) {
      source.addEventListener(event, e => handle(JSON.parse(e.data), e));
    }
    return source;
  }

  // ---- Lines ------------------------------------------------------------------------------------------------------

  views.lines = {
    source: null,
    open() { this.source = stream('api/lines/events', { lines: d => this.render(d) }); },
    close() { if (this.source) this.source.close(); this.source = null; },
    render(document) {
      took(document);
      const host = window.document.getElementById('lines');
      if (document.links.length === 0) {
        host.replaceChildren(el('p', { class: 'muted', text: 'No link is enabled.' }));
        return;
      }
      host.replaceChildren(...document.links.map(link => this.link(link)));
    },
    link(link) {
      const t = link.totals;
      return el('article', { class: 'card link', 'data-link': link.name },
        el('h2', null, link.name, ' ', badge(link.state)),
        el('dl', { class: 'facts' },
          el('dt', null, 'Endpoint'), el('dd', { class: 'endpoint' }, link.endpoint),
          el('dt', null, 'Line'), el('dd', { class: 'line' }, link.line),
          el('dt', null, 'Command set'), el('dd', null, link.commandSet),
          el('dt', null, 'Since'), el('dd', null, dateTime(link.since), link.detail ? ` — ${link.detail}` : ''),
          el('dt', null, 'Transactions/s'), el('dd', { class: 'rate' }, number(link.transactionsPerSecond, 1)),
          el('dt', null, 'Transactions'), el('dd', { class: 'transactions' }, t.transactions),
          el('dt', null, 'Errors'), el('dd', { class: 'errors' }, `${t.failures} (${failures(t.failuresByKind)})`),
          el('dt', null, 'Retries'), el('dd', { class: 'retries' }, t.retries),
          el('dt', null, 'Response'), el('dd', null, `last ${ms(t.lastResponseMs)}, average ${ms(t.averageResponseMs)}`)),
        el('h3', null, 'Units'),
        el('div', { class: 'scroll' }, el('table', { class: 'units' },
          el('thead', null, el('tr', null, ...['Unit', 'State', 'Since', 'Response (last / avg)', 'Transactions', 'Errors', 'Retries', 'Demotions', 'Last error']
            .map(h => el('th', null, h)))),
          el('tbody', null, ...link.units.map(u => this.unit(u))))),
        el('h3', null, 'Scan classes'),
        el('div', { class: 'scroll' }, el('table', { class: 'scan-classes' },
          el('thead', null, el('tr', null, ...['Unit', 'Interval', 'Cycle (last / avg)', 'Planned', 'Overruns', 'Groups'].map(h => el('th', null, h)))),
          el('tbody', null, ...link.scanClasses.map(c => el('tr', { 'data-scan-unit': c.unit, 'data-interval-ms': c.intervalMs },
            el('td', { 'data-label': 'Unit' }, c.unit), el('td', { 'data-label': 'Interval' }, interval(c.intervalMs)),
            el('td', { 'data-label': 'Cycle', class: c.measuredCycleMs > c.intervalMs ? 'cycle late' : 'cycle' }, `${ms(c.measuredCycleMs)} / ${ms(c.averageCycleMs)}`),
            el('td', { 'data-label': 'Planned' }, c.reads === null || c.reads === undefined ? '—' : `${c.reads} read${c.reads === 1 ? '' : 's'}, ≈ ${ms(c.estimatedCycleMs)}`),
            el('td', { 'data-label': 'Overruns', class: c.overruns > 0 ? 'overruns late' : 'overruns' }, c.overruns),
            el('td', { 'data-label': 'Groups' }, c.groups.join(', '))))))));
    },
    unit(u) {
      const f = u.figures;
      const events = el('ol', { class: 'events' }, ...u.events.map(e =>
        el('li', { 'data-state': e.state }, clockTime(e.time), ' ', badge(e.state), e.detail ? ` ${e.detail}` : '')));
      return el('tr', { 'data-unit': u.unit, class: `unit state-${u.state}` },
        el('td', { 'data-label': 'Unit' }, u.unit),
        el('td', { 'data-label': 'State', class: 'state' }, badge(u.state)),
        el('td', { 'data-label': 'Since' }, dateTime(u.since)),
        el('td', { 'data-label': 'Response' }, `${ms(f.lastResponseMs)} / ${ms(f.averageResponseMs)}`),
        el('td', { 'data-label': 'Transactions' }, f.transactions),
        el('td', { 'data-label': 'Errors' }, `${f.failures} (${failures(f.failuresByKind)})`),
        el('td', { 'data-label': 'Retries' }, f.retries),
        el('td', { 'data-label': 'Demotions' }, f.demotions),
        el('td', { 'data-label': 'Last error', class: 'last-error' },
          u.lastError ? el('span', null, u.lastError, el('span', { class: 'muted' }, ` (${dateTime(u.lastErrorTime)})`)) : '—',
          u.events.length > 0 ? events : null));
    },
  };

  // ---- Tags -------------------------------------------------------------------------------------------------------

  views.tags = {
    source: null,
    rows: [],      // by index: { tag, tr, cells, history }
    ageTimer: null,
    history: 60,
    open() {
      this.source = stream('api/tags/events', {
        snapshot: d => this.snapshot(d),
        changes: d => this.changes(d),
      });
      this.ageTimer = setInterval(() => this.ages(), 1000);
    },
    close() {
      if (this.source) this.source.close();
      this.source = null;
      clearInterval(this.ageTimer);
    },
    snapshot(document) {
      took(document);
      const body = window.document.querySelector('#tags tbody');
      this.rows = [];
      const trs = document.tags.map(tag => {
        const cells = {
          value: el('td', { class: 'value', 'data-label': 'Value' }),
          quality: el('td', { class: 'quality', 'data-label': 'Quality' }),
          age: el('td', { class: 'age', 'data-label': 'Age' }),
          spark: el('td', { class: 'spark', 'data-label': 'Recent' }),
        };
        const tr = el('tr', { 'data-tag': `${tag.link}/${tag.unit}/${tag.name}` },
          el('td', { 'data-label': 'Link' }, tag.link),
          el('td', { 'data-label': 'Unit' }, tag.unit),
          el('td', { class: 'name', 'data-label': 'Tag' }, tag.name),
          el('td', { 'data-label': 'Address' }, tag.address),
          el('td', { 'data-label': 'Type' }, tag.count > 1 ? `${tag.type} × ${tag.count}` : tag.type),
          cells.value, cells.quality, cells.age, cells.spark);
        const row = { tag, tr, cells, history: (tag.history || []).slice(), search: `${tag.link}/${tag.unit}/${tag.name} ${tag.address} ${tag.type}`.toLowerCase() };
        this.rows[tag.i] = row;
        this.paint(row);
        return tr;
      });
      body.replaceChildren(...trs);
      this.filter();
    },
    changes(document) {
      took(document);
      for (const change of document.tags) {
        const row = this.rows[change.i];
        if (!row) continue;
        Object.assign(row.tag, { value: change.value, quality: change.quality, time: change.time, readTime: change.readTime, error: change.error });
        const n = numeric(change.value);
        if (change.quality === 'good' && n !== null) {
          // One point an update: the gateway sends a tag at most once a refresh interval, as it keeps its history.
          row.history.push(n);
          if (row.history.length > this.history) row.history.shift();
        }
        this.paint(row);
      }
      this.filter();
    },
    paint(row) {
      const tag = row.tag;
      row.cells.value.textContent = display(tag.value, tag.type);
      row.cells.value.title = tag.error || '';
      row.cells.quality.replaceChildren(tag.quality ? badge(tag.quality) : '—');
      if (tag.error) row.cells.quality.append(el('div', { class: 'error', text: tag.error }));
      row.cells.age.textContent = age(tag.readTime);
      row.cells.spark.replaceChildren(sparkline(row.history));
      row.tr.className = tag.quality ? `quality-${tag.quality}` : '';
    },
    ages() {
      for (const row of this.rows) {
        if (row && !row.tr.hidden) row.cells.age.textContent = age(row.tag.readTime);
      }
    },
    filter() {
      const terms = window.document.getElementById('tag-filter').value.toLowerCase().split(/\s+/).filter(t => t);
      const quality = window.document.getElementById('quality-filter').value;
      let shown = 0;
      for (const row of this.rows) {
        if (!row) continue;
        const visible = terms.every(t => row.search.includes(t)) && (!quality || row.tag.quality === quality);
        row.tr.hidden = !visible;
        if (visible) shown++;
      }
      window.document.getElementById('tag-count').textContent = `${shown} of ${this.rows.length} tags`;
    },
  };

  function numeric(value) {
    if (typeof value === 'number') return Number.isFinite(value) ? value : null;
    if (typeof value === 'boolean') return value ? 1 : 0;
    return null;
  }

  function display(value, type) {
    if (value === null || value === undefined) return '—';
    const one = v => {
      if (typeof v === 'string') return type === 'string' ? `"${v}"` : v;
      if (typeof v === 'boolean') return v ? '1 (on)' : '0 (off)';
      if (type === 'word') return '0x' + v.toString(16).toUpperCase().padStart(4, '0');
      if (type === 'float' || type === 'double') return String(Number(v.toPrecision(7)));
      return String(v);
    };
    return Array.isArray(value) ? `[${value.map(one).join(', ')}]` : one(value);
  }

  // A small line of recent values, scaled to its own range.
  function sparkline(values) {
    const width = 80, height = 20;
    const svg = document.createElementNS('http://www.w3.org/2000/svg', 'svg');
    svg.setAttribute('viewBox', `0 0 ${width} ${height}`);
    svg.setAttribute('width', width);
    svg.setAttribute('height', height);
    svg.setAttribute('class', 'sparkline');
    if (values.length < 2) return svg;
    const min = Math.min(...values), max = Math.max(...values);
    const span = max - min || 1;
    const points = values.map((v, i) =>
      `${(i * (width - 2) / (values.length - 1) + 1).toFixed(1)},${(height - 2 - (v - min) * (height - 4) / span).toFixed(1)}`);
    const line = document.createElementNS('http://www.w3.org/2000/svg', 'polyline');
    line.setAttribute('points', points.join(' '));
    svg.append(line);
    const title = document.createElementNS('http://www.w3.org/2000/svg', 'title');
    title.textContent = `${values.length} recent values, ${min} to ${max}`;
    svg.append(title);
    return svg;
  }

  // ---- Line trace -------------------------------------------------------------------------------------------------

  views.trace = {
    source: null,
    running: false,
    link: null,
    last: 0,
    kept: 500,
    open() { this.links(); },
    close() { this.stop(); },
    async links() {
      const select = document.getElementById('trace-link');
      if (select.options.length > 0) return;
      const response = await fetch('api/trace', { headers: { Accept: 'application/json' } });
      const links = await response.json();
      select.replaceChildren(...links.map(l => el('option', { value: l, text: l })));
    },
    toggle() {
      if (this.running) this.stop(); else this.start();
    },
    start() {
      const select = document.getElementById('trace-link');
      if (!select.value) return;
      if (this.link !== select.value) { this.clear(); this.link = select.value; this.last = 0; }
      this.running = true;
      this.source = stream(`api/trace/${encodeURIComponent(this.link)}/events?after=${this.last}`, {
        tracing: () => this.state(`Tracing ${this.link}: its frames are taken while this runs.`),
        frames: d => this.frames(d),
      });
      document.getElementById('trace-toggle').textContent = 'Pause';
      this.state(`Starting the trace of ${this.link}…`);
    },
    stop() {
      if (this.source) this.source.close();
      this.source = null;
      if (!this.running) return;
      this.running = false;
      document.getElementById('trace-toggle').textContent = 'Resume';
      this.state(`Paused: the frames of ${this.link} are not taken now. Resume continues after the last one shown.`);
      this.separator(`paused at ${new Date().toLocaleTimeString([], { hour12: false })}`);
    },
    clear() {
      document.querySelector('#trace tbody').replaceChildren();
    },
    state(text) { document.getElementById('trace-state').textContent = text; },
    separator(text) {
      document.querySelector('#trace tbody').prepend(el('tr', { class: 'separator' }, el('td', { colspan: 8, text })));
    },
    frames(document) {
      const body = window.document.querySelector('#trace tbody');
      if (document.lost > 0) this.separator(`${document.lost} frame(s) not kept (too many at once)`);
      for (const f of document.frames) {
        this.last = f.seq;
        const explained = el('td', { class: 'explained', 'data-label': 'Explained' },
          f.name ? el('strong', null, f.name) : null,
          f.fields.length ? el('div', null, f.fields.join('; ')) : null,
          ...f.notes.map(n => el('div', { class: 'muted', text: n })),
          ...f.problems.map(p => el('div', { class: 'error', text: p })));
        body.prepend(el('tr', { 'data-seq': f.seq, class: `dir-${f.dir}${f.problems.length ? ' problem' : ''}` },
          el('td', { class: 'time', 'data-label': 'Time', title: f.time }, clockTime(f.time) + f.time.slice(23, 26)),
          el('td', { class: 'dir', 'data-label': 'Dir', title: f.dir === 'out' ? 'to the PLC' : 'from the PLC' }, f.dir === 'out' ? '→ PLC' : '← PLC'),
          el('td', { 'data-label': 'Unit' }, f.unit ?? '—'),
          el('td', { 'data-label': 'Command' }, f.header ?? '—'),
          el('td', { 'data-label': 'End code', title: f.endCodeMeaning || '' }, f.endCode ? `${f.endCode} ${f.endCodeMeaning || ''}` : '—'),
          el('td', { 'data-label': 'Latency' }, f.latencyMs === undefined ? '—' : ms(f.latencyMs)),
          el('td', { class: 'text', 'data-label': 'Frame' }, el('code', null, f.text)),
          explained));
      }
      while (body.rows.length > this.kept) body.deleteRow(body.rows.length - 1);
    },
  };

  // ---- Outputs ----------------------------------------------------------------------------------------------------

  views.outputs = {
    source: null,
    open() { this.source = stream('api/outputs/events', { outputs: d => this.render(d) }); },
    close() { if (this.source) this.source.close(); this.source = null; },
    render(document) {
      took(document);
      const host = window.document.getElementById('outputs');
      if (document.outputs.length === 0) {
        host.replaceChildren(el('p', { class: 'muted', text: 'No output is configured (Mqtt, Sparkplug): the gateway only logs what it reads.' }));
        return;
      }
      const count = v => v === null || v === undefined ? 'no queue' : String(v);
      host.replaceChildren(...document.outputs.map(o => el('article', { class: 'card output', 'data-output': o.name },
        el('h2', null, o.name, ' ', el('span', { class: `badge state-${o.connected ? 'online' : 'offline'}`, text: o.connected ? 'connected' : 'not connected' })),
        el('dl', { class: 'facts' },
          el('dt', null, 'State'), el('dd', { class: 'state' }, o.state),
          el('dt', null, 'Server in use'), el('dd', { class: 'server' }, o.server),
          el('dt', null, 'Connected since'), el('dd', null, dateTime(o.connectedSince)),
          el('dt', null, 'Queue depth'), el('dd', { class: 'queue' }, count(o.queueDepth)),
          el('dt', null, 'Unsent'), el('dd', { class: 'unsent' }, count(o.unsent)),
          el('dt', null, 'At risk'), el('dd', { class: 'at-risk' }, count(o.atRisk)),
          el('dt', null, 'Last publish'), el('dd', { class: 'last-publish' }, o.lastPublish ? `${dateTime(o.lastPublish)} (${age(o.lastPublish)} ago)` : 'none yet'),
          el('dt', null, 'Last error'), el('dd', null, o.lastError ? `${o.lastError} (${dateTime(o.lastErrorTime)})` : 'none'),
          o.detail ? el('dt', null, 'Detail') : null, o.detail ? el('dd', null, o.detail) : null))));
    },
  };

  // ---- navigation -------------------------------------------------------------------------------------------------

  function route() {
    const name = (location.hash || '#lines').slice(1);
    const view = views[name] ? name : 'lines';
    if (current === view) return;
    if (current) views[current].close();
    current = view;
    for (const section of document.querySelectorAll('.view')) section.hidden = section.id !== `view-${view}`;
    for (const a of document.querySelectorAll('nav a')) a.classList.toggle('active', a.dataset.view === view);
    views[view].open();
  }

  document.getElementById('tag-filter').addEventListener('input', () => views.tags.filter());
  document.getElementById('quality-filter').addEventListener('change', () => views.tags.filter());
  document.getElementById('trace-toggle').addEventListener('click', () => views.trace.toggle());
  document.getElementById('trace-clear').addEventListener('click', () => views.trace.clear());
  document.getElementById('trace-link').addEventListener('change', () => { if (views.trace.running) { views.trace.stop(); views.trace.start(); } });
  window.addEventListener('hashchange', route);
  route();
})();
