// rtlab viewer (docs/viewer.md): draws one case from the two data elements of this page.
//
// Trust: the page shows what student code did, so everything it reads is data. The strings come
// from a JSON element read with JSON.parse and are put in the page with textContent only; the
// numbers come from one deflated block of typed arrays, read with bounds checks (readBlob). No
// string is ever parsed as markup or run as code, and the page's policy (the meta element at the
// top) lets only its own three scripts run.
'use strict';

(function () {
  const OP_NAMES = ['box test', 'cell step', 'leaf entry', 'plane step', 'primitive test', 'mailbox repeat'];
  const OP = { BOX: 0, CELL: 1, LEAF: 2, PLANE: 3, PRIM: 4, REPEAT: 5 };
  const NO_NODE = 0xffffffff;
  const COLOURS = {
    interior: 0x2f6fd6, leaf: 0xe07b00, student: 0xff8c00, expected: 0x00a8c8, hitMarker: 0xff00ff, expectedMarker: 0x00c8ff,
    ray: 0xd4a000, primHit: 0x1fa83a, primMiss: 0xd62728, ddaExpected: 0x3b82f6, ddaStudent: 0xef4444, ddaBoth: 0xa855f7,
    shadowFree: 0x1fa83a, shadowBlocked: 0xd62728,
  };
  const MAX_LISTED_STEPS = 5000;
  const DDA_OPACITY = 0.6;  // the cells over white: tests/viewer/browser_test.py expects this blend
  const MAX_BLOB_BYTES = 512 * 1024 * 1024;

  const $ = (id) => document.getElementById(id);
  const status = (text) => { $('status').textContent = text; };
  const el = (tag, text, cls) => {
    const e = document.createElement(tag);
    if (text !== undefined) e.textContent = String(text);
    if (cls) e.className = cls;
    return e;
  };
  const fmt = (v) => (v === null || v === undefined ? 'none' : typeof v === 'number' ? (Number.isFinite(v) ? +v.toPrecision(6) + '' : String(v)) : String(v));

  // --- The data block: base64, deflated, then named typed arrays (viewer/viewer_blob.h) ---------
  async function readBlob(base64) {
    const text = base64.replace(/\s+/g, '');
    if (!/^[A-Za-z0-9+/]*={0,2}$/.test(text)) throw new Error('the data block is not base64');
    const binary = atob(text);
    const deflated = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; ++i) deflated[i] = binary.charCodeAt(i);
    const stream = new Blob([deflated]).stream().pipeThrough(new DecompressionStream('deflate'));
    const reader = stream.getReader();
    const chunks = [];
    let total = 0;
    for (;;) {
      const { done, value } = await reader.read();
      if (done) break;
      total += value.length;
      if (total > MAX_BLOB_BYTES) throw new Error('the data block is larger than a page may hold');
      chunks.push(value);
    }
    const bytes = new Uint8Array(total);
    let at = 0;
    for (const c of chunks) { bytes.set(c, at); at += c.length; }
    return parseSections(bytes.buffer);
  }

  function parseSections(buffer) {
    const view = new DataView(buffer);
    const types = { 1: Uint8Array, 2: Uint16Array, 3: Uint32Array, 4: Int32Array, 5: Float32Array, 6: Float64Array };
    if (buffer.byteLength < 8 || view.getUint32(0, true) !== 0x77765452) throw new Error('the data block has the wrong magic number');
    const count = view.getUint32(4, true);
    if (count > 100000) throw new Error('the data block has too many sections');
    const sections = new Map();
    let at = 8;
    const need = (n) => { if (n < 0 || at + n > buffer.byteLength) throw new Error('the data block ends too early'); };
    for (let s = 0; s < count; ++s) {
      need(1);
      const nameLength = view.getUint8(at); at += 1;
      need(nameLength + 1);
      let name = '';
      for (let i = 0; i < nameLength; ++i) name += String.fromCharCode(view.getUint8(at + i));
      if (!/^[A-Za-z0-9._]{1,63}$/.test(name)) throw new Error('the data block has a bad section name');
      at += nameLength;
      const Type = types[view.getUint8(at)]; at += 1;
      if (!Type) throw new Error('section ' + name + ' has an unknown element type');
      at = (at + 3) & ~3;
      need(4);
      const n = view.getUint32(at, true); at += 4;
      const bytes = n * Type.BYTES_PER_ELEMENT;
      need(bytes);
      sections.set(name, new Type(buffer.slice(at, at + bytes)));  // a copy: aligned for its type
      at = (at + bytes + 3) & ~3;
    }
    return {
      // The array of that name and type, or an empty one: a missing section is no data.
      get(name, Type) {
        const a = sections.get(name);
        return a instanceof Type ? a : new Type(0);
      },
      has: (name) => sections.has(name),
    };
  }

  // --- Small helpers ----------------------------------------------------------------------------
  function hashOptions() {
    const options = {};
    for (const part of location.hash.replace(/^#/, '').split('&')) {
      const [k, v] = part.split('=');
      if (k) options[decodeURIComponent(k)] = decodeURIComponent(v || '');
    }
    return options;
  }

  function depthColour(depth, maxDepth) {
    const c = new THREE.Color();
    c.setHSL((0.62 - 0.62 * (maxDepth > 0 ? depth / maxDepth : 0) + 1) % 1, 0.75, 0.45);
    return c;
  }

  // Few primitives to many: blue, teal, green, yellow, red.
  function countColour(count, maxCount) {
    const stops = [[0.23, 0.32, 0.78], [0.13, 0.6, 0.65], [0.3, 0.72, 0.3], [0.95, 0.8, 0.15], [0.85, 0.15, 0.1]];
    const x = maxCount > 1 ? Math.log(count) / Math.log(maxCount) : 0;
    const f = Math.min(Math.max(x, 0), 1) * (stops.length - 1);
    const i = Math.min(Math.floor(f), stops.length - 2), w = f - i;
    return new THREE.Color(...stops[i].map((v, k) => v * (1 - w) + stops[i + 1][k] * w));
  }

  function boxEdges(lo, hi) {
    const c = [[lo[0], lo[1], lo[2]], [hi[0], lo[1], lo[2]], [hi[0], hi[1], lo[2]], [lo[0], hi[1], lo[2]],
      [lo[0], lo[1], hi[2]], [hi[0], lo[1], hi[2]], [hi[0], hi[1], hi[2]], [lo[0], hi[1], hi[2]]];
    const e = [0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 0, 4, 1, 5, 2, 6, 3, 7];
    return e.map((i) => c[i]);
  }

  function lines(segments, colours, opacity) {
    const g = new THREE.BufferGeometry();
    const pos = new Float32Array(segments.length * 3);
    segments.forEach((p, i) => pos.set(p, i * 3));
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    let material;
    if (colours instanceof Float32Array) {
      g.setAttribute('color', new THREE.BufferAttribute(colours, 3));
      material = new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors, transparent: opacity < 1, opacity });
    } else {
      material = new THREE.LineBasicMaterial({ color: colours, transparent: opacity < 1, opacity });
    }
    return new THREE.LineSegments(g, material);
  }

  function solidBox(lo, hi, colour, opacity) {
    const g = new THREE.BoxBufferGeometry(hi[0] - lo[0] || 1e-6, hi[1] - lo[1] || 1e-6, hi[2] - lo[2] || 1e-6);
    const m = new THREE.Mesh(g, new THREE.MeshBasicMaterial({ color: colour, transparent: opacity < 1, opacity, depthWrite: opacity >= 1 }));
    m.position.set((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    return m;
  }

  // Where a ray enters and leaves a box (slab test), or null.
  function slab(o, d, lo, hi) {
    let t0 = -Infinity, t1 = Infinity;
    for (let a = 0; a < 3; ++a) {
      if (d[a] === 0) { if (o[a] < lo[a] || o[a] > hi[a]) return null; continue; }
      const ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
      t0 = Math.max(t0, Math.min(ta, tb));
      t1 = Math.min(t1, Math.max(ta, tb));
    }
    return t0 <= t1 ? [t0, t1] : null;
  }

  const finite3 = (p) => Number.isFinite(p[0]) && Number.isFinite(p[1]) && Number.isFinite(p[2]);

  // --- The page -----------------------------------------------------------------------------------
  async function main() {
    const meta = JSON.parse($('rtlab-text').textContent);
    if (typeof meta !== 'object' || meta === null || meta.format !== 1) throw new Error('the page data has an unknown format');
    const data = await readBlob($('rtlab-data').textContent);
    const options = hashOptions();

    $('title').textContent = typeof meta.title === 'string' && meta.title ? meta.title : 'rtlab viewer';
    document.title = $('title').textContent + ' - rtlab viewer';
    for (const note of Array.isArray(meta.notes) ? meta.notes : []) $('notes').appendChild(el('li', note));

    const frameArray = data.get('frame', Float32Array);
    const frame = { lo: Array.from(frameArray.slice(0, 3)), hi: Array.from(frameArray.slice(3, 6)) };
    if (frameArray.length !== 6 || !finite3(frame.lo) || !finite3(frame.hi)) { frame.lo = [-1, -1, -1]; frame.hi = [1, 1, 1]; }
    const extent = frame.hi.map((h, a) => h - frame.lo[a]);
    const dequantise = (q, a) => frame.lo[a] + (q / 65535) * extent[a];

    const has3d = ['mesh.pos', 'node.id', 'ray.data', 'dda.bounds'].some((name) => data.has(name));
    let view = null;
    if (has3d) view = makeView(meta, data, frame, options);
    if (view) {
      if (data.has('mesh.pos') || data.has('mesh.sphere')) addMesh(view, data, frame, extent);
      const resolution = data.get('grid.resolution', Int32Array);
      if (resolution.length === 3 && resolution.every((r) => r >= 1)) view.gridResolution = Array.from(resolution);
      if (meta.structure && data.has('node.id')) addStructure(view, meta, data, dequantise, options);
      if (data.has('dda.bounds')) addDda(view, data);
      if (Array.isArray(meta.rays) && meta.rays.length > 0) addRays(view, meta, data);
      view.render();
    }
    if (meta.images) addImages(view, meta, data);
    if (Array.isArray(meta.samplers) || Array.isArray(meta.estimators)) addRadiometry(meta, data);
    status(meta.geometryNote ? String(meta.geometryNote) : 'ready');
    document.body.dataset.state = 'ready';
  }

  // --- The 3D view --------------------------------------------------------------------------------
  function makeView(meta, data, frame, options) {
    $('scene-panel').hidden = false;
    const canvas = $('view3d');
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xffffff, 1);
    const scene = new THREE.Scene();
    const centre = new THREE.Vector3(...frame.lo.map((l, a) => (l + frame.hi[a]) / 2));
    const radius = Math.max(1e-6, new THREE.Vector3(...frame.hi).distanceTo(new THREE.Vector3(...frame.lo)) / 2);
    const camera = new THREE.PerspectiveCamera(50, 4 / 3, radius / 1000, radius * 1000);
    const controls = new THREE.OrbitControls(camera, canvas);
    scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    const light = new THREE.DirectionalLight(0xffffff, 0.6);
    scene.add(light);
    scene.add(light.target);
    const groups = {};
    for (const name of ['mesh', 'structure', 'highlight', 'trace', 'rays', 'markers', 'dda', 'pixel']) {
      groups[name] = new THREE.Group();
      scene.add(groups[name]);
    }
    let pending = false;
    const view = {
      renderer, scene, camera, controls, groups, frame, radius, centre, hover: null,
      render() {
        if (pending) return;
        pending = true;
        requestAnimationFrame(() => {
          pending = false;
          const w = canvas.clientWidth, h = canvas.clientHeight;
          if (canvas.width !== Math.floor(w * renderer.getPixelRatio()) || canvas.height !== Math.floor(h * renderer.getPixelRatio())) {
            renderer.setSize(w, h, false);
            camera.aspect = w / Math.max(h, 1);
            camera.updateProjectionMatrix();
          }
          light.position.copy(camera.position);
          light.target.position.copy(controls.target);
          renderer.render(scene, camera);
          document.body.dataset.frames = String(Number(document.body.dataset.frames || 0) + 1);
        });
      },
      resetCamera() {
        const c = options.camera ? options.camera.split(',').map(Number) : null;
        if (c && c.length === 6 && c.every(Number.isFinite)) {
          camera.position.set(c[0], c[1], c[2]);
          controls.target.set(c[3], c[4], c[5]);
        } else if (data.has('film')) {
          const f = data.get('film', Float64Array);
          camera.position.set(f[0], f[1], f[2]);
          controls.target.set(f[0] + f[3], f[1] + f[4], f[2] + f[5]);
          camera.up.set(f[9], f[10], f[11]).normalize();
        } else {
          camera.position.copy(centre).add(new THREE.Vector3(1.1, 0.8, 1.6).normalize().multiplyScalar(radius * 2.4));
          controls.target.copy(centre);
        }
        camera.lookAt(controls.target);
        controls.update();
        view.render();
      },
    };
    controls.addEventListener('change', () => view.render());
    window.addEventListener('resize', () => view.render());
    $('reset-camera').addEventListener('click', () => view.resetCamera());
    view.resetCamera();
    return view;
  }

  function addMesh(view, data, frame, extent) {
    const positions = data.get('mesh.pos', Uint16Array);
    const indices = data.get('mesh.index', Uint32Array);
    const vertexCount = Math.floor(positions.length / 3);
    const materials = {
      // Phong, because r111's Lambert material lights per vertex and has no flat shading: the
      // mesh carries no normals, each triangle is shaded by its own.
      ghost: new THREE.MeshPhongMaterial({ color: 0x9aa3b5, flatShading: true, shininess: 0, transparent: true, opacity: 0.22, depthWrite: false, side: THREE.DoubleSide }),
      solid: new THREE.MeshPhongMaterial({ color: 0xb8bfcc, flatShading: true, shininess: 0, side: THREE.DoubleSide }),
    };
    const meshes = [];
    if (vertexCount > 0 && indices.length >= 3) {
      // Indices beyond the vertices would make WebGL read out of bounds: such triangles are dropped.
      let valid = indices;
      if (indices.some((i) => i >= vertexCount)) valid = indices.filter((_, k) => indices[k - (k % 3)] < vertexCount && indices[k - (k % 3) + 1] < vertexCount && indices[k - (k % 3) + 2] < vertexCount);
      const g = new THREE.BufferGeometry();
      // 16-bit coordinates over the frame: the mesh's scale and position put them in place.
      g.setAttribute('position', new THREE.BufferAttribute(positions, 3, true));
      g.setIndex(new THREE.BufferAttribute(valid, 1));
      const mesh = new THREE.Mesh(g, materials.ghost);
      // three r111 bounds a normalised attribute by its raw integers, which would cull the mesh.
      mesh.frustumCulled = false;
      mesh.scale.set(extent[0] || 1, extent[1] || 1, extent[2] || 1);
      mesh.position.set(...frame.lo);
      view.groups.mesh.add(mesh);
      meshes.push(mesh);
      document.body.dataset.triangles = String(valid.length / 3);
    }
    const spheres = data.get('mesh.sphere', Float32Array);
    for (let i = 0; i + 3 < spheres.length && i < 4 * 2000; i += 4) {
      if (!finite3(spheres.subarray(i, i + 3)) || !(spheres[i + 3] > 0)) continue;
      const s = new THREE.Mesh(new THREE.SphereBufferGeometry(spheres[i + 3], 32, 16), materials.ghost);
      s.position.set(spheres[i], spheres[i + 1], spheres[i + 2]);
      view.groups.mesh.add(s);
      meshes.push(s);
    }
    const select = $('mesh-mode');
    const apply = () => {
      view.groups.mesh.visible = select.value !== 'hidden';
      for (const m of meshes) m.material = select.value === 'solid' ? materials.solid : materials.ghost;
      view.render();
    };
    const wanted = hashOptions().mesh;
    if (wanted && ['ghost', 'solid', 'hidden'].includes(wanted)) select.value = wanted;
    select.addEventListener('change', apply);
    apply();
    // The triangle of a primitive, for the trace's primitive tests and a leaf's list.
    view.triangle = (prim) => {
      if (!(prim >= 0) || prim * 3 + 2 >= indices.length) return null;
      const corner = (k) => {
        const v = indices[prim * 3 + k];
        if (v >= vertexCount) return null;
        return [0, 1, 2].map((a) => frame.lo[a] + (positions[v * 3 + a] / 65535) * extent[a]);
      };
      const c = [corner(0), corner(1), corner(2)];
      return c.every((p) => p) ? c : null;
    };
    view.sphere = (prim) => {
      const k = prim - indices.length / 3;
      if (!(k >= 0) || 4 * k + 3 >= spheres.length) return null;
      return { centre: Array.from(spheres.subarray(4 * k, 4 * k + 3)), radius: spheres[4 * k + 3] };
    };
  }

  // A group drawing primitives (triangles or spheres) in one colour.
  function primitivesGroup(view, prims, colour) {
    const group = new THREE.Group();
    const tris = [];
    for (const p of prims) {
      const t = view.triangle ? view.triangle(p) : null;
      if (t) { tris.push(...t); continue; }
      const s = view.sphere ? view.sphere(p) : null;
      if (s && finite3(s.centre) && s.radius > 0) {
        const m = new THREE.Mesh(new THREE.SphereBufferGeometry(s.radius * 1.002, 24, 12), new THREE.MeshBasicMaterial({ color: colour, transparent: true, opacity: 0.6 }));
        m.position.set(...s.centre);
        group.add(m);
      }
    }
    if (tris.length) {
      const g = new THREE.BufferGeometry();
      const pos = new Float32Array(tris.length * 3);
      tris.forEach((p, i) => pos.set(p, i * 3));
      g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
      group.add(new THREE.Mesh(g, new THREE.MeshBasicMaterial({ color: colour, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: -2 })));
    }
    return group;
  }

  // --- Structures (framework/accel/structure_drawing.h) -------------------------------------------
  function addStructure(view, meta, data, dequantise, options) {
    const info = meta.structure;
    const ids = data.get('node.id', Uint32Array);
    const n = ids.length;
    const parent = data.get('node.parent', Uint32Array), depth = data.get('node.depth', Uint16Array);
    const flags = data.get('node.flags', Uint8Array), count = data.get('node.count', Uint32Array);
    const qbox = data.get('node.box', Uint16Array), values = data.get('node.value', Float32Array);
    const primStart = data.get('node.primStart', Uint32Array), prims = data.get('node.prims', Uint32Array);
    if (parent.length !== n || depth.length !== n || flags.length !== n || count.length !== n || qbox.length !== 6 * n)
      throw new Error('the structure data is inconsistent');
    const nodes = [];
    let maxDepth = 0, maxCount = 1;
    for (let i = 0; i < n; ++i) {
      const lo = [0, 1, 2].map((a) => dequantise(qbox[6 * i + a], a)), hi = [0, 1, 2].map((a) => dequantise(qbox[6 * i + 3 + a], a));
      nodes.push({ id: ids[i], parent: parent[i], depth: depth[i], leaf: (flags[i] & 1) !== 0, visited: (flags[i] & 2) !== 0,
        hasBox: (flags[i] & 4) === 0 && info.boxesMeaningful !== false, count: count[i], lo, hi,
        value: values.length === n ? values[i] : null });
      maxDepth = Math.max(maxDepth, depth[i]);
      if (flags[i] & 1) maxCount = Math.max(maxCount, count[i]);
    }
    const nodePrims = (i) => {
      const s = primStart[i];
      if (s === NO_NODE || s === undefined || s + nodes[i].count > prims.length) return null;
      return prims.subarray(s, s + nodes[i].count);
    };
    view.nodes = nodes;
    view.nodePrims = nodePrims;

    const style = info.style;
    const total = `${info.nodes} nodes` + (info.carried < info.reachable ? (style === 'cells' ? `, ${info.carried} of them on this page (the occupied cells` +
      (info.completeDepth === info.maxDepth ? '' : ', up to the cap,') + ' and every cell a trace visits)' :
      `, ${info.carried} of them on this page (whole levels down to depth ${info.completeDepth}, and every node a trace visits)`) : '');
    $('structure-info').textContent = `${fmt(meta.accelerator)}: ${total}, depth ${info.maxDepth}, ${info.references} primitive references` +
      (info.malformed > 0 ? `; ${info.malformed} child links out of range or repeated were left out` : '');
    $('structure-toggle-box').hidden = false;
    const toggle = $('structure-toggle');
    if (options.structure === 'off') toggle.checked = false;
    toggle.addEventListener('change', () => { view.groups.structure.visible = toggle.checked; view.render(); });
    view.groups.structure.visible = toggle.checked;

    const legend = $('legend');
    const swatch = (colour, label) => {
      const s = el('span');
      const i = el('i');
      i.style.background = '#' + new THREE.Color(colour).getHexString();
      s.append(i, label);
      legend.appendChild(s);
    };

    let hoverTargets = [];
    if (style === 'cells') {
      // Occupied cells by how many primitives they hold; every carried leaf at once.
      const leaves = nodes.map((node, i) => i).filter((i) => nodes[i].leaf && nodes[i].count > 0 && nodes[i].hasBox);
      if (leaves.length <= 30000) {
        const segs = [], colours = new Float32Array(leaves.length * 24 * 3);
        leaves.forEach((i, k) => {
          const c = countColour(nodes[i].count, maxCount);
          for (const p of boxEdges(nodes[i].lo, nodes[i].hi)) segs.push(p);
          for (let v = 0; v < 24; ++v) colours.set([c.r, c.g, c.b], (k * 24 + v) * 3);
        });
        view.groups.structure.add(lines(segs, colours, 0.9));
      } else {
        const pos = new Float32Array(leaves.length * 3), colours = new Float32Array(leaves.length * 3);
        let size = Infinity;
        leaves.forEach((i, k) => {
          pos.set(nodes[i].lo.map((l, a) => (l + nodes[i].hi[a]) / 2), 3 * k);
          const c = countColour(nodes[i].count, maxCount);
          colours.set([c.r, c.g, c.b], 3 * k);
          size = Math.min(size, nodes[i].hi[0] - nodes[i].lo[0]);
        });
        const g = new THREE.BufferGeometry();
        g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
        g.setAttribute('color', new THREE.BufferAttribute(colours, 3));
        view.groups.structure.add(new THREE.Points(g, new THREE.PointsMaterial({ size: Number.isFinite(size) ? size * 0.6 : 1, vertexColors: THREE.VertexColors })));
      }
      for (const k of [1, Math.round(Math.sqrt(maxCount)), maxCount]) swatch(countColour(k, maxCount), `${k} primitive${k === 1 ? '' : 's'}`);
      hoverTargets = leaves;
    } else {
      // A level at a time: the slider picks the depth.
      $('depth-box').hidden = false;
      const slider = $('depth');
      slider.max = String(maxDepth);
      const initial = Number(options.depth);
      slider.value = String(Number.isInteger(initial) && initial >= 0 && initial <= maxDepth ? initial : Math.min(maxDepth, 3));
      const planeNode = data.get('plane.node', Uint32Array), planeStart = data.get('plane.start', Uint32Array);
      const planeVerts = data.get('plane.verts', Float32Array);
      const drawLevel = () => {
        const d = Number(slider.value);
        $('depth-value').textContent = String(d);
        const group = view.groups.structure;
        while (group.children.length) group.remove(group.children[0]);
        const interiorSegs = [], leafSegs = [], olderLeafSegs = [];
        hoverTargets = [];
        nodes.forEach((node, i) => {
          if (!node.hasBox) return;
          if (node.depth === d) {
            for (const p of boxEdges(node.lo, node.hi)) (node.leaf ? leafSegs : interiorSegs).push(p);
            hoverTargets.push(i);
          } else if (node.leaf && node.depth < d && style === 'levels') {
            for (const p of boxEdges(node.lo, node.hi)) olderLeafSegs.push(p);
          }
        });
        if (style === 'levels' && interiorSegs.length) group.add(lines(interiorSegs, COLOURS.interior, 0.9));
        if (leafSegs.length) group.add(lines(leafSegs, COLOURS.leaf, 0.95));
        if (olderLeafSegs.length) group.add(lines(olderLeafSegs, COLOURS.leaf, 0.25));
        if (style === 'planes') {
          for (let k = 0; k < planeNode.length && k + 1 < planeStart.length; ++k) {
            const i = planeNode[k];
            if (i >= n || nodes[i].depth > d) continue;
            const from = planeStart[k], to = planeStart[k + 1];
            if (to > planeVerts.length / 3 || to - from < 3) continue;
            const tris = [];
            for (let v = from + 1; v + 1 < to; ++v) for (const w of [from, v, v + 1]) tris.push(planeVerts[3 * w], planeVerts[3 * w + 1], planeVerts[3 * w + 2]);
            if (!tris.every(Number.isFinite)) continue;
            const g = new THREE.BufferGeometry();
            g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(tris), 3));
            const exact = nodes[i].depth === d;
            group.add(new THREE.Mesh(g, new THREE.MeshBasicMaterial({ color: depthColour(nodes[i].depth, maxDepth), transparent: true,
              opacity: exact ? 0.45 : 0.12, side: THREE.DoubleSide, depthWrite: false })));
            if (exact) hoverTargets.push(i);
          }
        }
        view.render();
      };
      slider.addEventListener('input', drawLevel);
      drawLevel();
      if (style === 'levels') { swatch(COLOURS.interior, 'interior nodes at this depth'); swatch(COLOURS.leaf, 'leaves (faint: shallower leaves)'); }
      else {
        swatch(depthColour(0, maxDepth), 'planes, coloured by depth (down to the slider; the slider\'s own depth stronger)');
        if (info.boxesMeaningful !== false) swatch(COLOURS.leaf, 'leaves at this depth');
      }
    }

    // Hover: the nearest drawn box under the pointer, its numbers, and a leaf's primitives.
    const canvas = $('view3d');
    const raycaster = new THREE.Raycaster();
    let hovered = -1;
    canvas.addEventListener('mousemove', (event) => {
      const r = canvas.getBoundingClientRect();
      raycaster.setFromCamera(new THREE.Vector2(((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1), view.camera);
      const o = raycaster.ray.origin.toArray(), d = raycaster.ray.direction.toArray();
      let best = -1, bestT = Infinity;
      for (const i of hoverTargets) {
        const s = slab(o, d, nodes[i].lo, nodes[i].hi);
        if (s && s[1] >= 0 && Math.max(s[0], 0) < bestT) { bestT = Math.max(s[0], 0); best = i; }
      }
      if (best === hovered) return;
      hovered = best;
      const box = $('hover');
      const group = view.groups.highlight;
      while (group.children.length) group.remove(group.children[0]);
      if (best < 0) { box.hidden = true; view.render(); return; }
      const node = nodes[best];
      let textLines = [`node ${node.id}, depth ${node.depth}`, node.leaf ? `leaf of ${node.count} primitives` : 'interior' + (node.count ? `, ${node.count} primitives in it` : '')];
      if (node.value !== null && meta.structure.valueName) textLines.push(`${meta.structure.valueName}: ${(100 * node.value).toFixed(2)} %`);
      box.textContent = textLines.join('\n');
      box.hidden = false;
      const list = nodePrims(best);
      if (list && list.length) group.add(primitivesGroup(view, list, COLOURS.leaf));
      view.render();
    });
  }

  // --- a3's DDA: expected and student cells in one grid --------------------------------------------
  function addDda(view, data) {
    const b = data.get('dda.bounds', Float32Array), res = data.get('dda.resolution', Int32Array);
    if (b.length !== 6 || res.length !== 3 || !res.every((r) => r >= 1 && r <= 4096)) return;
    const lo = [b[0], b[1], b[2]], hi = [b[3], b[4], b[5]];
    if (!finite3(lo) || !finite3(hi)) return;
    const width = [0, 1, 2].map((a) => (hi[a] - lo[a]) / res[a]);
    const cells = new Map();
    const mark = (list, bit) => {
      for (let k = 0; k + 2 < list.length; k += 3) {
        const c = [list[k], list[k + 1], list[k + 2]];
        if (!c.every((v, a) => v >= 0 && v < res[a])) continue;
        const key = c.join(',');
        cells.set(key, { cell: c, bits: (cells.get(key) ? cells.get(key).bits : 0) | bit });
      }
    };
    mark(data.get('dda.expected', Int32Array), 1);
    mark(data.get('dda.student', Int32Array), 2);
    const group = view.groups.dda;
    group.add(lines(boxEdges(lo, hi), 0x555555, 1));
    for (const { cell, bits } of cells.values()) {
      const clo = cell.map((c, a) => lo[a] + (c + 0.08) * width[a]), chi = cell.map((c, a) => lo[a] + (c + 0.92) * width[a]);
      group.add(solidBox(clo, chi, bits === 3 ? COLOURS.ddaBoth : bits === 1 ? COLOURS.ddaExpected : COLOURS.ddaStudent, DDA_OPACITY));
    }
    const legend = $('legend');
    for (const [colour, label] of [[COLOURS.ddaExpected, 'expected cells only'], [COLOURS.ddaStudent, 'your cells only'], [COLOURS.ddaBoth, 'cells of both walks']]) {
      const s = el('span');
      const i = el('i');
      i.style.background = '#' + new THREE.Color(colour).getHexString();
      s.append(i, label);
      legend.appendChild(s);
    }
  }

  // --- Rays and their traces -----------------------------------------------------------------------
  function readTrace(data, prefix) {
    const kind = data.get(prefix + '.kind', Uint8Array);
    const t = {
      kind, hit: data.get(prefix + '.hit', Uint8Array), index: data.get(prefix + '.index', Uint32Array),
      t: data.get(prefix + '.t', Float32Array), tFar: data.get(prefix + '.tfar', Float32Array), node: data.get(prefix + '.node', Uint32Array),
      box: data.get(prefix + '.box', Float32Array), boxOf: [],
    };
    const n = kind.length;
    if ([t.hit, t.index, t.t, t.tFar, t.node].some((a) => a.length !== n)) throw new Error('trace ' + prefix + ' is inconsistent');
    let b = 0;
    for (let i = 0; i < n; ++i) t.boxOf.push(kind[i] === OP.BOX ? b++ : -1);
    if (b * 6 !== t.box.length) throw new Error('trace ' + prefix + ' has the wrong number of boxes');
    return t;
  }

  function stepText(view, trace, i) {
    const k = trace.kind[i];
    let s = `${OP_NAMES[k] || 'unknown'}`;
    const node = trace.node[i] !== NO_NODE && view.nodes && view.nodes[trace.node[i]] ? view.nodes[trace.node[i]] : null;
    if (k === OP.BOX) s += node ? ` node ${node.id}` : ' (box of no carried node)';
    if (k === OP.BOX) s += trace.hit[i] ? ` hit, enters at t=${fmt(trace.t[i])}` : ' miss';
    if (k === OP.CELL) s += node ? ' ' + cellName(view, node) : '';
    if (k === OP.PLANE) s += node ? ` node ${node.id}` : '';
    if (k === OP.LEAF) s += ` node ${trace.index[i]}`;
    if (k === OP.PRIM) s += ` prim ${trace.index[i]}` + (trace.hit[i] ? ` hit at t=${fmt(trace.t[i])}` : ' miss');
    if (k === OP.REPEAT) s += ` prim ${trace.index[i]} (tested before)`;
    if ((k === OP.PRIM || k === OP.REPEAT) && node) s += node.leaf ? ` in ${view.gridResolution ? cellName(view, node) : 'leaf ' + node.id}` : '';
    return s;
  }

  // A grid's cell by its coordinates (node 1 + cellIndex of a grid's view), else by its node.
  function cellName(view, node) {
    const r = view.gridResolution;
    const c = node.id - 1;
    if (!r || node.depth !== 1 || c < 0 || c >= r[0] * r[1] * r[2]) return `node ${node.id}`;
    return `cell (${c % r[0]}, ${Math.floor(c / r[0]) % r[1]}, ${Math.floor(c / (r[0] * r[1]))})`;
  }

  function addRays(view, meta, data) {
    $('ray-panel').hidden = false;
    const rayData = data.get('ray.data', Float32Array);
    const select = $('ray-select');
    meta.rays.forEach((r, i) => select.appendChild(el('option', `${i}: ${r.label || 'ray ' + i}`)));
    const options = hashOptions();
    const wanted = Number(options.ray);
    if (Number.isInteger(wanted) && wanted >= 0 && wanted < meta.rays.length) select.selectedIndex = wanted;
    let state = null;

    const show = () => {
      const r = select.selectedIndex;
      const info = meta.rays[r];
      if (!info || rayData.length < 8 * (r + 1)) return;
      const o = Array.from(rayData.subarray(8 * r, 8 * r + 3)), d = Array.from(rayData.subarray(8 * r + 3, 8 * r + 6));
      const tMin = rayData[8 * r + 6], tMax = rayData[8 * r + 7];
      const student = info.studentTrace ? readTrace(data, `trace.${r}.s`) : null;
      const expected = info.expectedTrace ? readTrace(data, `trace.${r}.e`) : null;
      state = { r, info, o, d, tMin, tMax, student, expected, step: -1 };
      // The ray, drawn to where it leaves the scene (or its tMax).
      for (const g of ['rays', 'markers', 'trace']) while (view.groups[g].children.length) view.groups[g].remove(view.groups[g].children[0]);
      const exit = slab(o, d, view.frame.lo, view.frame.hi);
      let tEnd = Math.min(tMax, exit ? exit[1] : view.radius * 4 / Math.hypot(...d));
      if (!Number.isFinite(tEnd) || tEnd < 0) tEnd = view.radius * 2 / Math.hypot(...d);
      if (finite3(o) && finite3(d)) {
        const start = o.map((v, a) => v + Math.max(tMin, 0) * d[a]), end = o.map((v, a) => v + tEnd * d[a]);
        const ray = lines([start, end], COLOURS.ray, 1);
        ray.material.depthTest = false;
        ray.material.transparent = true;  // drawn after the see-through mesh
        ray.renderOrder = 10;
        view.groups.rays.add(ray);
      }
      // Answers.
      const body = $('answers').querySelector('tbody');
      body.textContent = '';
      const describe = (a) => !a || a.kind === 'none' ? 'no answer' : a.kind === 'any' ? (a.hit ? 'blocked' : 'not blocked') :
        a.hit ? `prim ${fmt(a.prim)} at t=${fmt(a.t)}` : 'a miss';
      for (const [label, a] of [['your code', info.student], [`expected (${info.expectedSource || 'reference'})`, info.expected]]) {
        const tr = el('tr');
        tr.append(el('th', label), el('td', describe(a)));
        body.appendChild(tr);
      }
      // Step lists.
      for (const [trace, id, heading] of [[student, 'student-steps', 'your code'], [expected, 'expected-steps', 'expected']]) {
        const ol = $(id);
        ol.textContent = '';
        const h = $(id === 'student-steps' ? 'student-heading' : 'expected-heading');
        const traceMeta = id === 'student-steps' ? info.studentTrace : info.expectedTrace;
        h.textContent = heading + (trace ? `: ${trace.kind.length} steps` + (traceMeta && traceMeta.dropped > 0 ? ` (+${traceMeta.dropped} not recorded)` : '') : ': no trace');
        if (!trace) continue;
        for (let i = 0; i < Math.min(trace.kind.length, MAX_LISTED_STEPS); ++i) {
          const li = el('li', stepText(view, trace, i));
          li.dataset.kind = String(trace.kind[i]);
          li.dataset.index = String(trace.index[i]);
          li.addEventListener('click', () => goTo(i));
          ol.appendChild(li);
        }
        if (trace.kind.length > MAX_LISTED_STEPS) ol.appendChild(el('li', `… ${trace.kind.length - MAX_LISTED_STEPS} more (step to them with the buttons)`));
      }
      const diff = Number.isInteger(info.firstDifference) ? info.firstDifference : null;
      $('step-diff').hidden = !(diff !== null && diff >= 0);
      $('difference').textContent = diff === null ? (student && !expected ? 'no expected trace to compare with: the expected answer is the oracle\'s' : '') :
        diff < 0 ? 'the two traces are the same, step for step' : `the traces part at step ${diff}`;
      for (const id of ['student-steps', 'expected-steps']) {
        const item = $(id).children[diff];
        if (diff !== null && diff >= 0 && item) item.classList.add('differs');
      }
      goTo(Number.isInteger(Number(options.step)) && options.step !== undefined && options.step !== '' ? Number(options.step) : -1);
    };

    const length = () => Math.max(state.student ? state.student.kind.length : 0, state.expected ? state.expected.kind.length : 0);

    // Step k of both traces: everything visited up to it, the node of step k, then the hits.
    const goTo = (k) => {
      if (!state) return;
      const n = length();
      k = Math.max(-1, Math.min(k, n));  // -1: before the first step; n: after the last
      state.step = k;
      const group = view.groups.trace;
      while (group.children.length) group.remove(group.children[0]);
      const markers = view.groups.markers;
      while (markers.children.length) markers.remove(markers.children[0]);
      const parts = [];
      for (const [trace, colour, who] of [[state.expected, COLOURS.expected, 'expected'], [state.student, COLOURS.student, 'yours']]) {
        if (!trace) continue;
        const upTo = Math.min(k, trace.kind.length - 1);
        // Nodes visited so far, faint; the current one solid.
        const seen = new Set();
        const segs = [];
        for (let i = 0; i <= upTo; ++i) {
          const v = trace.node[i];
          if (v !== NO_NODE && view.nodes && view.nodes[v] && view.nodes[v].hasBox && !seen.has(v)) {
            seen.add(v);
            for (const p of boxEdges(view.nodes[v].lo, view.nodes[v].hi)) segs.push(p);
          }
        }
        if (segs.length) group.add(lines(segs, colour, 0.5));
        if (k >= 0 && k < trace.kind.length) {
          const v = trace.node[k];
          if (v !== NO_NODE && view.nodes && view.nodes[v] && view.nodes[v].hasBox) {
            group.add(solidBox(view.nodes[v].lo, view.nodes[v].hi, colour, 0.25));
          } else if (trace.kind[k] === OP.BOX && trace.boxOf[k] >= 0) {
            const b = trace.box.subarray(6 * trace.boxOf[k], 6 * trace.boxOf[k] + 6);
            if (b.every(Number.isFinite)) group.add(lines(boxEdges([b[0], b[1], b[2]], [b[3], b[4], b[5]]), colour, 1));
          }
          if (trace.kind[k] === OP.PRIM || trace.kind[k] === OP.REPEAT)
            group.add(primitivesGroup(view, [trace.index[k]], trace.hit[k] ? COLOURS.primHit : COLOURS.primMiss));
          parts.push(`${who}, step ${k}: ${stepText(view, trace, k)}`);
        } else if (k >= trace.kind.length) {
          parts.push(`${who}: done after ${trace.kind.length} steps`);
        }
      }
      // The hits, once the walk is over (or when there is no walk to step through).
      if (k >= n || n === 0) {
        for (const [answer, colour] of [[state.info.expected, COLOURS.expectedMarker], [state.info.student, COLOURS.hitMarker]]) {
          if (!answer || answer.kind !== 'closest' || !answer.hit || typeof answer.t !== 'number') continue;
          const p = state.o.map((v, a) => v + answer.t * state.d[a]);
          if (!finite3(p)) continue;
          const g = new THREE.BufferGeometry();
          g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(p), 3));
          // Transparent, so it is drawn in the last pass, after the see-through mesh, by its renderOrder.
          const m = new THREE.Points(g, new THREE.PointsMaterial({ color: colour, size: 14, sizeAttenuation: false, depthTest: false, transparent: true }));
          m.renderOrder = 20;
          markers.add(m);
        }
      }
      $('step-current').textContent = parts.join('\n');
      $('step-count').textContent = k < 0 ? `before step 0 of ${n}` : k >= n ? `after the last of ${n} steps` : `step ${k} of ${n}`;
      for (const id of ['student-steps', 'expected-steps']) {
        const ol = $(id);
        for (const li of ol.querySelectorAll('li.current')) li.classList.remove('current');
        const item = k >= 0 && k < MAX_LISTED_STEPS ? ol.children[k] : null;
        if (item) { item.classList.add('current'); item.scrollIntoView({ block: 'nearest' }); }
      }
      document.body.dataset.step = String(k);
      view.render();
    };

    $('step-first').addEventListener('click', () => goTo(0));
    $('step-prev').addEventListener('click', () => goTo(state.step - 1));
    $('step-next').addEventListener('click', () => goTo(state.step + 1));
    $('step-last').addEventListener('click', () => goTo(length()));
    $('step-diff').addEventListener('click', () => goTo(state.info.firstDifference));
    document.addEventListener('keydown', (e) => {
      if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
      if (e.key === 'ArrowRight') goTo(state.step + 1);
      else if (e.key === 'ArrowLeft') goTo(state.step - 1);
      else if (e.key === 'Home') goTo(0);
      else if (e.key === 'End') goTo(length());
    });
    select.addEventListener('change', show);
    show();
  }

  // --- Image to ray --------------------------------------------------------------------------------
  function addImages(view, meta, data) {
    const info = meta.images;
    const width = Number(info.width), height = Number(info.height);
    if (!(width > 0 && height > 0)) return;
    $('image-panel').hidden = false;
    $('image-legend').textContent = info.legend || '';
    const film = data.get('film', Float64Array);
    const hitT = data.get('pixel.t', Float32Array);
    const lights = data.get('light.pos', Float32Array), blocked = data.get('pixel.shadow', Uint8Array);
    const lightCount = Math.floor(lights.length / 3);
    const marks = [];
    const captions = { render: 'render', heat: 'traversal cost (steps + primitive tests per camera ray)', reference: 'POV-Ray reference', difference: 'difference from the reference' };
    for (const key of ['render', 'heat', 'reference', 'difference']) {
      if (typeof info[key] !== 'string' || !/^[a-z]+\.png$/.test(info[key])) continue;
      const figure = el('figure');
      const img = el('img');
      img.src = info[key];
      img.width = width;
      img.height = height;
      img.alt = captions[key];
      img.dataset.image = key;
      const mark = el('div', undefined, 'pixel-mark');
      mark.hidden = true;
      marks.push(mark);
      figure.append(img, mark, el('figcaption', captions[key]));
      $('images').appendChild(figure);
      img.addEventListener('click', (event) => {
        // The image's content box: its border is not part of it.
        const r = img.getBoundingClientRect();
        const x = event.clientX - r.left - img.clientLeft, y = event.clientY - r.top - img.clientTop;
        pick(Math.floor((x / img.clientWidth) * width), Math.floor((y / img.clientHeight) * height));
      });
    }

    // The camera ray of a pixel exactly as the renderer makes it (framework/scene/camera.h).
    const pick = (x, y) => {
      if (!(x >= 0 && x < width && y >= 0 && y < height) || film.length !== 14) return;
      for (const m of marks) { m.hidden = false; m.style.left = `${x - 3}px`; m.style.top = `${y - 3}px`; }
      const fx = (x + 0.5) / film[12] - 0.5, fy = 0.5 - (y + 0.5) / film[13];
      const dir = [0, 1, 2].map((a) => film[3 + a] + fx * film[6 + a] + fy * film[9 + a]);
      const len = Math.hypot(...dir);
      const d = dir.map((v) => v / len), o = [film[0], film[1], film[2]];
      const pixel = y * width + x;
      const t = hitT.length === width * height ? hitT[pixel] : NaN;
      const lines_ = [`pixel (${x}, ${y}): ` + (Number.isFinite(t) ? `hits at t=${fmt(t)}` : hitT.length ? 'a miss' : 'no hit data')];
      if (view) {
        const group = view.groups.pixel;
        while (group.children.length) group.remove(group.children[0]);
        const far = Number.isFinite(t) ? t : view.radius * 3;
        const end = o.map((v, a) => v + far * d[a]);
        const ray = lines([o, end], COLOURS.ray, 1);
        ray.material.depthTest = false;
        group.add(ray);
        if (Number.isFinite(t)) {
          for (let l = 0; l < lightCount; ++l) {
            const isBlocked = blocked.length === width * height * lightCount && blocked[pixel * lightCount + l] !== 0;
            const lp = Array.from(lights.subarray(3 * l, 3 * l + 3));
            const shadow = lines([end, lp], isBlocked ? COLOURS.shadowBlocked : COLOURS.shadowFree, 1);
            shadow.material.depthTest = false;
            group.add(shadow);
            lines_.push(`shadow ray to light ${l}: ${isBlocked ? 'blocked' : 'reaches it'}`);
          }
          const g = new THREE.BufferGeometry();
          g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(end), 3));
          const m = new THREE.Points(g, new THREE.PointsMaterial({ color: COLOURS.hitMarker, size: 12, sizeAttenuation: false, depthTest: false, transparent: true }));
          m.renderOrder = 20;
          group.add(m);
        }
        view.render();
      }
      if (typeof meta.pixelCommand === 'string') lines_.push(`to step through this pixel's traversal: ${meta.pixelCommand.replace('X,Y', `${x},${y}`)}`);
      $('pixel-info').textContent = lines_.join('\n');
      document.body.dataset.pixel = `${x},${y}`;
    };
    if (Array.isArray(info.selected)) pick(Number(info.selected[0]), Number(info.selected[1]));
  }

  // --- a6: samplers and estimators ----------------------------------------------------------------
  function canvas2d(w, h) {
    const c = el('canvas');
    c.width = w;
    c.height = h;
    return [c, c.getContext('2d')];
  }

  function addRadiometry(meta, data) {
    $('radiometry-panel').hidden = false;
    (meta.samplers || []).forEach((s, i) => {
      const card = el('div', undefined, 'card');
      card.appendChild(el('h3', s.name));
      if (s.error) { card.appendChild(el('p', s.error, 'error')); $('samplers').appendChild(card); return; }
      const prefix = `a6.s.${i}`;
      const u = data.get(prefix + '.u', Float32Array), mapped = data.get(prefix + '.mapped', Float32Array);
      const shape = data.get(prefix + '.shape', Float32Array);
      const observed = data.get(prefix + '.observed', Float64Array), expected = data.get(prefix + '.expected', Float64Array);
      // The unit square.
      const [square, sq] = canvas2d(200, 200);
      sq.fillStyle = '#fff'; sq.fillRect(0, 0, 200, 200);
      sq.fillStyle = '#2f6fd6';
      for (let k = 0; k + 1 < u.length; k += 2) sq.fillRect(4 + u[k] * 192 - 1, 196 - u[k + 1] * 192 - 1, 2, 2);
      // The domain.
      const [domain, dm] = canvas2d(200, 200);
      drawDomain(dm, s.domain, mapped, shape);
      // The histogram against the exact counts, and where the counts deviate.
      const [hist, hg] = canvas2d(300, 200);
      const [dev, dg] = canvas2d(300, 200);
      const rows = Number(s.rows), cols = Number(s.cols);
      const layout = rows > 0 && cols > 0 && rows * cols + 1 === observed.length && observed.length === expected.length;
      drawHistogram(hg, layout ? marginal(observed, rows, cols) : observed, layout ? marginal(expected, rows, cols) : expected);
      drawDeviations(dg, observed, expected, layout ? rows : 1, layout ? cols : observed.length);
      const row = el('div');
      row.append(square, domain, hist, dev);
      card.appendChild(row);
      card.appendChild(el('p', `the u in the unit square | the samples on the ${s.domain}` + (s.domain === 'sphere' ? ' (blue z >= 0, red below)' : '') +
        ' | ' + (layout ? `histogram of z from ${fmt(s.zMin)} to 1: bars your samples, line the exact counts` : 'histogram per cell: bars your samples, line the exact counts') +
        ' | each cell\'s deviation (O - E) / sqrt(E): blue fewer, red more than expected, white within 1' + (layout ? ' (rows z, columns phi)' : ''), 'info'));
      card.appendChild(el('p', `cells: ${s.cells}`, 'info'));
      card.appendChild(el('p', `chi-square ${fmt(s.chiSquare)} with ${fmt(s.dof)} degrees of freedom: p = ${fmt(s.p)}`, 'info'));
      $('samplers').appendChild(card);
    });
    const estimators = meta.estimators || [];
    if (estimators.length) {
      const card = el('div', undefined, 'card');
      const [plot, pg] = canvas2d(640, 360);
      const series = estimators.map((e, i) => ({ name: e.name, error: e.error, n: data.get(`a6.e.${i}.n`, Float64Array), err: data.get(`a6.e.${i}.error`, Float64Array), slope: e.slope }));
      drawConvergence(pg, series);
      card.appendChild(plot);
      const list = el('ul');
      series.forEach((s, i) => {
        const li = el('li', s.error ? `${s.name}: ${s.error}` : `${s.name}: slope ${fmt(s.slope)} (plain Monte Carlo: -0.5)`);
        li.style.color = seriesColour(i);
        list.appendChild(li);
      });
      card.appendChild(list);
      $('estimators').appendChild(card);
    }
  }

  function drawDomain(g, domain, mapped, shape) {
    g.fillStyle = '#fff'; g.fillRect(0, 0, 200, 200);
    g.strokeStyle = '#888';
    const n = Math.floor(mapped.length / 3);
    const dot = (x, y, colour) => { g.fillStyle = colour; g.fillRect(x - 1, y - 1, 2, 2); };
    if (domain === 'triangle' || domain === 'spherical triangle') {
      // Triangle: its plane; spherical triangle: the directions' gnomonic projection about their mean.
      const p = [0, 1, 2].map((k) => [shape[3 * k], shape[3 * k + 1], shape[3 * k + 2]]);
      const origin = [shape[9], shape[10], shape[11]];
      let pts = [], corners;
      if (domain === 'triangle') {
        const e1 = p[1].map((v, a) => v - p[0][a]), e2 = p[2].map((v, a) => v - p[0][a]);
        const len = Math.hypot(...e1) || 1, ux = e1.map((v) => v / len);
        const dot3 = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        const v2 = e2.map((v, a) => v - dot3(e2, ux) * ux[a]), vy = v2.map((v) => v / (Math.hypot(...v2) || 1));
        const flat = (q) => { const r = q.map((v, a) => v - p[0][a]); return [dot3(r, ux), dot3(r, vy)]; };
        corners = p.map(flat);
        for (let k = 0; k < n; ++k) pts.push(flat([mapped[3 * k], mapped[3 * k + 1], mapped[3 * k + 2]]));
      } else {
        const dirs = p.map((q) => { const r = q.map((v, a) => v - origin[a]); const l = Math.hypot(...r) || 1; return r.map((v) => v / l); });
        const mean = [0, 1, 2].map((a) => dirs[0][a] + dirs[1][a] + dirs[2][a]);
        const ml = Math.hypot(...mean) || 1, w = mean.map((v) => v / ml);
        const helper = Math.abs(w[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
        const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
        let ux = cross(w, helper); const ul = Math.hypot(...ux) || 1; ux = ux.map((v) => v / ul);
        const vy = cross(w, ux);
        const project = (d) => { const dw = d[0] * w[0] + d[1] * w[1] + d[2] * w[2]; return dw > 1e-6 ? [(d[0] * ux[0] + d[1] * ux[1] + d[2] * ux[2]) / dw, (d[0] * vy[0] + d[1] * vy[1] + d[2] * vy[2]) / dw] : [NaN, NaN]; };
        corners = dirs.map(project);
        for (let k = 0; k < n; ++k) pts.push(project([mapped[3 * k], mapped[3 * k + 1], mapped[3 * k + 2]]));
      }
      const xs = corners.map((c) => c[0]), ys = corners.map((c) => c[1]);
      const lo = [Math.min(...xs), Math.min(...ys)], size = Math.max(Math.max(...xs) - lo[0], Math.max(...ys) - lo[1]) || 1;
      const map = (c) => [10 + ((c[0] - lo[0]) / size) * 180, 190 - ((c[1] - lo[1]) / size) * 180];
      g.beginPath();
      corners.map(map).forEach((c, k) => (k ? g.lineTo(...c) : g.moveTo(...c)));
      g.closePath(); g.stroke();
      for (const q of pts) if (Number.isFinite(q[0]) && Number.isFinite(q[1])) dot(...map(q), '#d6472f');
      return;
    }
    // Directions: the upper half seen from +z (and, for the sphere, the lower one in red).
    const r = domain === 'cone' ? Math.sqrt(Math.max(0, 1 - shape[12] * shape[12])) || 1 : 1;
    const scale = 90 / (domain === 'cone' && shape[12] > 0 ? r : 1);
    g.beginPath(); g.arc(100, 100, 90, 0, 2 * Math.PI); g.stroke();
    for (let k = 0; k < n; ++k) {
      const x = mapped[3 * k], y = mapped[3 * k + 1], z = mapped[3 * k + 2];
      if (!Number.isFinite(x + y + z)) continue;
      dot(100 + x * scale, 100 - y * scale, z >= 0 ? '#2f6fd6' : '#d6472f');
    }
  }

  function drawHistogram(g, observed, expected) {
    g.fillStyle = '#fff'; g.fillRect(0, 0, 300, 200);
    const n = Math.min(observed.length, expected.length);
    if (!n) return;
    let max = 0;
    for (let i = 0; i < n; ++i) max = Math.max(max, observed[i], expected[i]);
    if (!(max > 0) || !Number.isFinite(max)) return;
    const w = 280 / n;
    g.fillStyle = '#8fb3ea';
    for (let i = 0; i < n; ++i) { const h = (observed[i] / max) * 180; g.fillRect(10 + i * w, 190 - h, Math.max(w - 0.3, 0.5), h); }
    g.strokeStyle = '#d62728'; g.lineWidth = 1.5;
    g.beginPath();
    for (let i = 0; i < n; ++i) { const x = 10 + (i + 0.5) * w, y = 190 - (expected[i] / max) * 180; i ? g.lineTo(x, y) : g.moveTo(x, y); }
    g.stroke();
  }

  // Per band: the sum of its cols cells.
  function marginal(counts, rows, cols) {
    const out = new Float64Array(rows);
    for (let r = 0; r < rows; ++r) for (let c = 0; c < cols; ++c) out[r] += counts[r * cols + c];
    return out;
  }

  function drawDeviations(g, observed, expected, rows, cols) {
    g.fillStyle = '#fff'; g.fillRect(0, 0, 300, 200);
    const w = 280 / cols, h = 180 / rows;
    for (let r = 0; r < rows; ++r) for (let c = 0; c < cols; ++c) {
      const i = r * cols + c;
      if (!(expected[i] > 0)) continue;
      const z = (observed[i] - expected[i]) / Math.sqrt(expected[i]);
      const x = Math.max(-1, Math.min(1, (Math.abs(z) - 1) / 4)) * Math.sign(z);
      const fade = Math.round(255 * (1 - Math.abs(x)));
      g.fillStyle = x > 0 ? `rgb(255,${fade},${fade})` : `rgb(${fade},${fade},255)`;
      if (Math.abs(z) <= 1) g.fillStyle = '#fff';
      g.fillRect(10 + c * w, 190 - (r + 1) * h, Math.ceil(w), Math.ceil(h));
    }
    g.strokeStyle = '#999'; g.strokeRect(10, 10, 280, 180);
  }

  function seriesColour(i) { return ['#2f6fd6', '#d6472f', '#1fa83a', '#a855f7', '#e0a000', '#00a8c8', '#555'][i % 7]; }

  function drawConvergence(g, series) {
    g.fillStyle = '#fff'; g.fillRect(0, 0, 640, 360);
    const pts = [];
    for (const s of series) for (let i = 0; i < Math.min(s.n.length, s.err.length); ++i) if (s.n[i] > 0 && s.err[i] > 0) pts.push([Math.log10(s.n[i]), Math.log10(s.err[i])]);
    if (!pts.length) return;
    const x0 = Math.min(...pts.map((p) => p[0])), x1 = Math.max(...pts.map((p) => p[0])) || x0 + 1;
    const y0 = Math.min(...pts.map((p) => p[1])), y1 = Math.max(...pts.map((p) => p[1])) || y0 + 1;
    const map = (p) => [50 + ((p[0] - x0) / (x1 - x0 || 1)) * 570, 330 - ((p[1] - y0) / (y1 - y0 || 1)) * 300];
    g.strokeStyle = '#999'; g.strokeRect(50, 30, 570, 300);
    g.fillStyle = '#333'; g.font = '12px sans-serif';
    g.fillText('log10 samples', 300, 352); g.fillText('log10 RMS relative error', 4, 20);
    series.forEach((s, k) => {
      g.strokeStyle = seriesColour(k); g.lineWidth = 2; g.beginPath();
      let first = true;
      for (let i = 0; i < Math.min(s.n.length, s.err.length); ++i) {
        if (!(s.n[i] > 0 && s.err[i] > 0)) continue;
        const [x, y] = map([Math.log10(s.n[i]), Math.log10(s.err[i])]);
        first ? g.moveTo(x, y) : g.lineTo(x, y);
        first = false;
      }
      g.stroke();
    });
  }

  main().catch((e) => {
    document.body.dataset.state = 'error';
    status('this viewer cannot show its data: ' + (e && e.message ? e.message : String(e)));
    console.error('rtlab viewer:', e);
  });
})();
