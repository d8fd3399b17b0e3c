// The frame tree in the side panel: collapsible nodes with each frame's rate and age, a search
// box that filters by name, and the trees not connected to the fixed frame.

export function formatAge(seconds) {
  if (!Number.isFinite(seconds)) return '';
  if (seconds < 1) return `${Math.round(seconds * 1000)} ms`;
  if (seconds < 100) return `${seconds.toFixed(1)} s`;
  return `${Math.round(seconds)} s`;
}

export function formatRate(hz) {
  if (!Number.isFinite(hz)) return '';
  return hz < 10 ? `${hz.toFixed(1)} Hz` : `${Math.round(hz)} Hz`;
}

export class TreePanel {
  // onSelect(name) is called when a frame is clicked.
  constructor({ list, search, count, unconnectedBox, onSelect }) {
    this.list = list;
    this.search = search;
    this.count = count;
    this.unconnectedBox = unconnectedBox;
    this.onSelect = onSelect;
    this.items = new Map();
    this.collapsed = new Set();
    this.selected = null;
    this.builtVersion = -1;
    this.flagsKey = '';
    this.unconnectedKey = '';

    list.addEventListener('click', (event) => {
      const li = event.target.closest('li[data-frame]');
      if (!li) return;
      const name = li.dataset.frame;
      if (event.target.classList.contains('twisty')) {
        this.toggle(name);
      } else {
        this.onSelect(name);
      }
    });
    unconnectedBox.addEventListener('click', (event) => {
      const root = event.target.closest('[data-root]');
      if (root) this.onSelect(root.dataset.root);
    });
    search.addEventListener('input', () => this.applyFilter());
  }

  get listedCount() {
    return this.items.size;
  }

  // Follows the store: rebuilds the nodes when the tree's shape changed, else updates them.
  update(store) {
    if (store.structureVersion !== this.builtVersion) {
      this.rebuild(store);
      this.builtVersion = store.structureVersion;
    }
    for (const [name, item] of this.items) {
      const frame = store.frames.get(name);
      let info = '';
      let title = name;
      if (frame) {
        info = frame.static ? 'static' : `${formatRate(frame.rate_hz)} · ${formatAge(frame.age_s)}`;
        title = `${name}\nparent: ${frame.parent}\nauthority: ${frame.authority}`;
      } else {
        title = `${name}\n(root)`;
      }
      if (item.info.textContent !== info) item.info.textContent = info;
      if (item.row.title !== title) item.row.title = title;
    }
    this.updateFlags(store);
  }

  // Greys stale frames and marks those not connected to the fixed frame; cheap when unchanged.
  updateFlags(store) {
    const unconnected = new Set();
    for (const tree of store.unconnected) for (const name of tree.frames) unconnected.add(name);
    const key = [...store.stale].join('\n') + '|' + [...unconnected].join('\n');
    if (key !== this.flagsKey) {
      this.flagsKey = key;
      for (const [name, item] of this.items) {
        item.li.classList.toggle('stale', store.stale.has(name));
        item.li.classList.toggle('unconnected', unconnected.has(name));
      }
    }
    this.renderUnconnected(store);
  }

  renderUnconnected(store) {
    const key = store.fixedFrame + '|' +
      store.unconnected.map((tree) => `${tree.root}:${tree.frames.length}`).join(',');
    if (key === this.unconnectedKey) return;
    this.unconnectedKey = key;
    this.unconnectedBox.replaceChildren();
    if (store.unconnected.length === 0) return;
    const heading = document.createElement('div');
    heading.textContent = `Not connected to ${store.fixedFrame || 'the fixed frame'}:`;
    this.unconnectedBox.appendChild(heading);
    const list = document.createElement('ul');
    for (const tree of store.unconnected) {
      const item = document.createElement('li');
      const root = document.createElement('span');
      root.className = 'tree-root';
      root.dataset.root = tree.root;
      root.textContent = tree.root;
      item.append(root, ` (${tree.frames.length} frame${tree.frames.length === 1 ? '' : 's'})`);
      list.appendChild(item);
    }
    this.unconnectedBox.appendChild(list);
  }

  rebuild(store) {
    const children = new Map();
    const parents = new Map();
    for (const [name, frame] of store.frames) {
      parents.set(name, frame.parent);
      if (!children.has(frame.parent)) children.set(frame.parent, []);
      children.get(frame.parent).push(name);
    }
    // Roots: those the server names, and any parent that is nobody's child.
    const roots = new Set(store.roots);
    for (const parent of children.keys()) if (!parents.has(parent)) roots.add(parent);

    this.items.clear();
    const built = new Set();
    const build = (name) => {
      built.add(name);
      const li = document.createElement('li');
      li.dataset.frame = name;
      const row = document.createElement('div');
      row.className = 'frame-row';
      const twisty = document.createElement('span');
      twisty.className = 'twisty';
      const label = document.createElement('span');
      label.className = 'frame-name';
      label.textContent = name;
      const info = document.createElement('span');
      info.className = 'frame-info';
      row.append(twisty, label, info);
      li.appendChild(row);
      const kids = (children.get(name) || []).filter((kid) => !built.has(kid)).sort();
      if (kids.length > 0) {
        twisty.textContent = '▾';
        const ul = document.createElement('ul');
        for (const kid of kids) ul.appendChild(build(kid));
        li.appendChild(ul);
        if (this.collapsed.has(name)) {
          li.classList.add('collapsed');
          twisty.textContent = '▸';
        }
      }
      li.classList.toggle('selected', name === this.selected);
      this.items.set(name, { li, row, info, twisty });
      return li;
    };
    const fragment = document.createDocumentFragment();
    for (const root of [...roots].sort()) fragment.appendChild(build(root));
    // A loop in what the server sent would leave frames unreached: list them at the top level.
    for (const name of [...parents.keys()].sort()) {
      if (!built.has(name)) fragment.appendChild(build(name));
    }
    this.list.replaceChildren(fragment);
    this.count.textContent = `(${this.items.size})`;
    this.flagsKey = '';
    this.applyFilter();
  }

  toggle(name) {
    const item = this.items.get(name);
    if (!item || !item.li.querySelector('ul')) return;
    const collapsed = !this.collapsed.has(name);
    if (collapsed) this.collapsed.add(name); else this.collapsed.delete(name);
    item.li.classList.toggle('collapsed', collapsed);
    item.twisty.textContent = collapsed ? '▸' : '▾';
  }

  setSelected(name) {
    const previous = this.items.get(this.selected);
    if (previous) previous.li.classList.remove('selected');
    this.selected = name;
    const item = this.items.get(name);
    if (!item) return;
    item.li.classList.add('selected');
    // Open the ancestors so that the selected frame shows.
    for (let li = item.li.parentElement.closest('li[data-frame]'); li;
      li = li.parentElement.closest('li[data-frame]')) {
      if (this.collapsed.has(li.dataset.frame)) this.toggle(li.dataset.frame);
    }
    item.row.scrollIntoView({ block: 'nearest' });
  }

  // Shows the frames whose name holds the search text, with their ancestors.
  applyFilter() {
    const query = this.search.value.trim().toLowerCase();
    this.list.classList.toggle('filtering', query !== '');
    const visit = (li) => {
      let keep = query === '' || li.dataset.frame.toLowerCase().includes(query);
      const ul = li.lastElementChild.tagName === 'UL' ? li.lastElementChild : null;
      if (ul) {
        for (const child of ul.children) {
          if (visit(child)) keep = true;
        }
      }
      li.classList.toggle('filtered-out', !keep);
      return keep;
    };
    for (const li of this.list.children) visit(li);
  }
}
