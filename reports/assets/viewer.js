// The image viewer of a job page (reports/image_viewer.cpp writes its markup): two panes side by
// side or one pane with a wipe between them, each showing a layer (reference, image, difference,
// FLIP, the reference's standard error); zoom and pan shared by both panes, nearest-neighbour when
// magnified; exposure in stops and a false-colour toggle; the values of every layer at the pixel
// under the pointer. Layers come from the job's viewer data (linear half floats registered in
// window.gibViewerData by scripts beside the page, image/viewer_data.h), so exposure and readout
// work on the real values; a run without that data falls back to its PNGs (display only).
// The view is kept in the address's #fragment (a=, b=, mode=, wipe=, zoom=, cx=, cy=, exposure=,
// false=, probe=x,y), so a view can be linked to and a screenshot scripted. Plain ES5.
(function () {
  'use strict';
  function each(list, f) { Array.prototype.forEach.call(list, f); }

  // Half float bits to float: a 65536-entry table, built on first use.
  var halfTable = null;
  function halfToFloatTable() {
    if (halfTable) return halfTable;
    halfTable = new Float32Array(65536);
    for (var h = 0; h < 65536; h++) {
      var sign = h & 0x8000 ? -1 : 1, exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
      var value;
      if (exponent === 0) value = mantissa * Math.pow(2, -24);
      else if (exponent === 31) value = mantissa ? NaN : Infinity;
      else value = (1 + mantissa / 1024) * Math.pow(2, exponent - 15);
      halfTable[h] = sign * value;
    }
    return halfTable;
  }

  function decodeLayer(entry) {
    var text = atob(entry.half), count = text.length >> 1, table = halfToFloatTable();
    var values = new Float32Array(count);
    for (var i = 0; i < count; i++)
      values[i] = table[text.charCodeAt(2 * i) | (text.charCodeAt(2 * i + 1) << 8)];
    return { width: entry.width, height: entry.height, channels: entry.channels, values: values };
  }

  // sRGB encoding of [0, 1] (IEC 61966-2-1), as the report's PNGs use (Standard view).
  var srgbTable = new Uint8ClampedArray(4097);
  for (var i = 0; i <= 4096; i++) {
    var v = i / 4096;
    srgbTable[i] = Math.round(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055));
  }
  function srgbByte(v) { return srgbTable[Math.round(Math.min(Math.max(v, 0), 1) * 4096)]; }

  function hexBytes(hex) {
    var bytes = new Uint8ClampedArray(hex.length >> 1);
    for (var i = 0; i < bytes.length; i++) bytes[i] = parseInt(hex.substr(2 * i, 2), 16);
    return bytes;
  }

  function formatValue(v) {
    if (!isFinite(v)) return String(v);
    if (v === 0) return '0';
    var a = Math.abs(v);
    return a >= 1e4 || a < 1e-3 ? v.toExponential(3) : v.toPrecision(4);
  }

  function parseFragment() {
    var state = {};
    location.hash.replace(/^#/, '').split('&').forEach(function (part) {
      var eq = part.indexOf('=');
      if (eq > 0) state[decodeURIComponent(part.slice(0, eq))] = decodeURIComponent(part.slice(eq + 1));
    });
    return state;
  }

  function Viewer(root) {
    var self = this;
    this.root = root;
    this.width = +root.getAttribute('data-width');
    this.height = +root.getAttribute('data-height');
    this.magma = hexBytes(root.getAttribute('data-magma'));
    this.layers = {};
    var data = window.gibViewerData || {};
    var sources = [root.getAttribute('data-reference-data'), root.getAttribute('data-job-data')];
    sources.forEach(function (id) {
      var entry = id && data[id];
      if (!entry) return;
      Object.keys(entry.layers).forEach(function (name) {
        var layer = decodeLayer(entry.layers[name]);
        if (layer.width === self.width && layer.height === self.height) self.layers[name] = layer;
      });
    });
    this.linear = !!(this.layers.reference || this.layers.image);
    this.pngs = {};
    each(root.querySelectorAll('img.layer'), function (img) { self.pngs[img.getAttribute('data-layer')] = img; });
    this.names = [];
    each(root.querySelector('select[data-role="a"]').options, function (o) { self.names.push(o.value); });
    // Pane size: the image enlarged by a whole factor up to 512 pixels, or shrunk to 512.
    var fit = this.width > 0 ? Math.max(1, Math.floor(512 / this.width)) : 1;
    if (this.width > 512) fit = 512 / this.width;
    this.fitZoom = fit;
    this.paneWidth = Math.round(this.width * fit);
    this.paneHeight = Math.round(this.height * fit);
    this.view = { a: root.getAttribute('data-a'), b: root.getAttribute('data-b'), mode: 'side', wipe: 0.5,
                  zoom: fit, cx: this.width / 2, cy: this.height / 2, exposure: 0, falseColour: false, probe: null };
    this.cache = {};
    this.canvases = root.querySelectorAll('canvas');
    each(this.canvases, function (canvas) {
      canvas.width = self.paneWidth;
      canvas.height = self.paneHeight;
      canvas.style.width = self.paneWidth + 'px';
      canvas.style.height = self.paneHeight + 'px';
    });
    this.control = function (role) { return root.querySelector('[data-role="' + role + '"]'); };
    if (!this.linear) {
      this.control('exposure').disabled = true;
      this.control('false-colour').disabled = true;
    }
    var fragment = parseFragment();
    this.applyFragment(fragment);
    this.bind();
    this.draw();
    // The PNGs of a run without linear data decode after this script ran: draw again once they
    // have (before the page's self-check, which listens to the same event later).
    if (!this.linear) window.addEventListener('load', function () { self.cache = {}; self.draw(); });
    root.setAttribute('data-viewer-state', 'ready');
    // A link to a view shows the view, not the top of the page ("focus=1": the viewer alone,
    // for a screenshot or a large screen).
    if (fragment.focus === '1') document.body.className += ' viewer-focus';
    else if (fragment.mode || fragment.zoom || fragment.probe) root.scrollIntoView();
  }

  Viewer.prototype.applyFragment = function (f) {
    var v = this.view, names = this.names;
    if (names.indexOf(f.a) >= 0) v.a = f.a;
    if (names.indexOf(f.b) >= 0) v.b = f.b;
    if (f.mode === 'wipe' || f.mode === 'side') v.mode = f.mode;
    if (isFinite(+f.wipe) && f.wipe !== undefined) v.wipe = Math.min(Math.max(+f.wipe, 0), 1);
    if (+f.zoom > 0) v.zoom = Math.min(Math.max(+f.zoom, this.fitZoom / 4), 256);
    if (f.cx !== undefined && isFinite(+f.cx)) v.cx = +f.cx;
    if (f.cy !== undefined && isFinite(+f.cy)) v.cy = +f.cy;
    if (this.linear && f.exposure !== undefined && isFinite(+f.exposure)) v.exposure = Math.min(Math.max(+f.exposure, -20), 20);
    if (this.linear && f['false'] !== undefined) v.falseColour = f['false'] === '1';
    if (f.probe) {
      var p = f.probe.split(',');
      if (p.length === 2 && isFinite(+p[0]) && isFinite(+p[1])) v.probe = { x: Math.floor(+p[0]), y: Math.floor(+p[1]) };
    }
  };

  Viewer.prototype.writeFragment = function () {
    var v = this.view;
    var parts = ['a=' + v.a, 'b=' + v.b, 'mode=' + v.mode, 'wipe=' + v.wipe.toFixed(3), 'zoom=' + v.zoom,
                 'cx=' + v.cx.toFixed(2), 'cy=' + v.cy.toFixed(2), 'exposure=' + v.exposure, 'false=' + (v.falseColour ? 1 : 0)];
    if (v.probe) parts.push('probe=' + v.probe.x + ',' + v.probe.y);
    try { history.replaceState(null, '', '#' + parts.join('&')); } catch (e) { /* some file:// pages refuse */ }
  };

  // The linear value of a layer at a pixel: RGB (or one channel repeated), or null where the layer
  // has no linear data.
  Viewer.prototype.value = function (name, x, y) {
    if (name === 'difference') {
      var a = this.value('image', x, y), b = this.value('reference', x, y);
      return a && b ? [Math.abs(a[0] - b[0]), Math.abs(a[1] - b[1]), Math.abs(a[2] - b[2])] : null;
    }
    var layer = this.layers[name];
    if (!layer) return null;
    var o = (y * layer.width + x) * layer.channels, d = layer.values;
    return layer.channels >= 3 ? [d[o], d[o + 1], d[o + 2]] : [d[o], d[o], d[o]];
  };

  // The layer at its own resolution, through exposure and the display transform (or false
  // colour), as a canvas; cached per setting.
  Viewer.prototype.layerCanvas = function (name) {
    var v = this.view, linear = this.linear && (name === 'difference' ? this.layers.image && this.layers.reference : this.layers[name]);
    var key = name + (linear ? '|' + v.exposure + '|' + v.falseColour : '');
    if (this.cache[key]) return this.cache[key];
    var canvas = document.createElement('canvas');
    canvas.width = this.width;
    canvas.height = this.height;
    var ctx = canvas.getContext('2d');
    if (!linear) {
      var img = this.pngs[name];
      // At its own size: the difference and FLIP PNGs carry a colour bar below the picture.
      if (img && img.complete && img.naturalWidth > 0) ctx.drawImage(img, 0, 0);
      return (this.cache[key] = canvas);
    }
    var pixels = ctx.createImageData(this.width, this.height), out = pixels.data;
    var scale = Math.pow(2, v.exposure), magma = this.magma;
    var scalar = name === 'flip';  // FLIP is an error in [0, 1]: always its colour map, no exposure
    for (var y = 0; y < this.height; y++)
      for (var x = 0; x < this.width; x++) {
        var rgb = this.value(name, x, y), o = 4 * (y * this.width + x);
        out[o + 3] = 255;
        if (!(isFinite(rgb[0]) && isFinite(rgb[1]) && isFinite(rgb[2]))) {
          out[o] = 255; out[o + 1] = 0; out[o + 2] = 255;  // as the PNGs: a renderer bug shows
          continue;
        }
        if (scalar || v.falseColour) {
          var t = scalar ? rgb[0] : (0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]) * scale;
          var m = 3 * Math.round(Math.min(Math.max(t, 0), 1) * 255);
          out[o] = magma[m]; out[o + 1] = magma[m + 1]; out[o + 2] = magma[m + 2];
        } else {
          out[o] = srgbByte(rgb[0] * scale); out[o + 1] = srgbByte(rgb[1] * scale); out[o + 2] = srgbByte(rgb[2] * scale);
        }
      }
    ctx.putImageData(pixels, 0, 0);
    return (this.cache[key] = canvas);
  };

  Viewer.prototype.drawLayer = function (ctx, name) {
    var v = this.view;
    ctx.save();
    ctx.setTransform(v.zoom, 0, 0, v.zoom, this.paneWidth / 2 - v.cx * v.zoom, this.paneHeight / 2 - v.cy * v.zoom);
    ctx.imageSmoothingEnabled = v.zoom < 1;  // magnified: every pixel a sharp square
    ctx.drawImage(this.layerCanvas(name), 0, 0);
    if (v.probe) {
      ctx.lineWidth = 2 / v.zoom;
      ctx.strokeStyle = '#00e5ff';
      ctx.strokeRect(v.probe.x, v.probe.y, 1, 1);
    }
    ctx.restore();
  };

  Viewer.prototype.draw = function () {
    var v = this.view, root = this.root;
    var b = this.canvases[1], a = this.canvases[0];
    b.hidden = v.mode === 'wipe';
    this.control('wipe').hidden = v.mode !== 'wipe';
    var ctx = a.getContext('2d');
    ctx.fillStyle = '#808080';
    ctx.fillRect(0, 0, a.width, a.height);
    if (v.mode === 'wipe') {
      // Left of the line: layer A; right of it: layer B.
      var x = Math.round(v.wipe * a.width);
      this.drawLayer(ctx, v.b);
      ctx.save();
      ctx.beginPath();
      ctx.rect(0, 0, x, a.height);
      ctx.clip();
      ctx.fillRect(0, 0, x, a.height);
      this.drawLayer(ctx, v.a);
      ctx.restore();
      ctx.fillStyle = '#ffffff';
      ctx.fillRect(x - 1, 0, 2, a.height);
    } else {
      this.drawLayer(ctx, v.a);
      var other = b.getContext('2d');
      other.fillStyle = '#808080';
      other.fillRect(0, 0, b.width, b.height);
      this.drawLayer(other, v.b);
    }
    root.querySelector('select[data-role="a"]').value = v.a;
    root.querySelector('select[data-role="b"]').value = v.b;
    each(root.querySelectorAll('button[data-mode]'), function (button) {
      button.setAttribute('aria-pressed', String(button.getAttribute('data-mode') === v.mode));
    });
    this.control('exposure').value = v.exposure;
    this.control('exposure-value').textContent = (v.exposure >= 0 ? '+' : '') + v.exposure + ' EV';
    this.control('false-colour').checked = v.falseColour;
    this.control('wipe').value = v.wipe;
    var zoomText = function (z) { return String(Math.round(z * 100) / 100); };
    this.control('zoom').textContent = (v.zoom >= 1 ? zoomText(v.zoom) : '1/' + zoomText(1 / v.zoom)) + '×';
    if (v.probe) this.readout(v.probe.x, v.probe.y, true);
    root.setAttribute('data-view', JSON.stringify(v));
  };

  // The pixel under a point of a pane, or null outside the image.
  Viewer.prototype.pixelAt = function (canvas, clientX, clientY) {
    var rect = canvas.getBoundingClientRect(), v = this.view;
    var sx = (clientX - rect.left) * this.paneWidth / rect.width, sy = (clientY - rect.top) * this.paneHeight / rect.height;
    var x = Math.floor((sx - this.paneWidth / 2) / v.zoom + v.cx), y = Math.floor((sy - this.paneHeight / 2) / v.zoom + v.cy);
    return x >= 0 && y >= 0 && x < this.width && y < this.height ? { x: x, y: y, sx: sx, sy: sy } : null;
  };

  Viewer.prototype.readout = function (x, y, pinned) {
    var self = this, parts = ['pixel (' + x + ', ' + y + ')' + (pinned ? ' pinned' : '')];
    ['reference', 'image', 'difference', 'flip', 'stderr'].forEach(function (name) {
      var value = self.value(name, x, y);
      if (!value) return;
      var single = name === 'flip' || self.layers[name] && self.layers[name].channels === 1;
      parts.push(name + ' ' + (single ? formatValue(value[0]) : value.map(formatValue).join(' ')));
    });
    var image = this.value('image', x, y), reference = this.value('reference', x, y);
    if (image && reference) {
      var lum = function (c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; };
      var r = lum(reference);
      if (r > 0) parts.push('relative error ' + formatValue((lum(image) - r) / r));
    }
    if (!this.linear) parts.push('(no linear data in this run: values are not available)');
    this.control('readout').textContent = parts.join(' · ');
  };

  Viewer.prototype.zoomAbout = function (factor, canvas, clientX, clientY) {
    // Without a canvas (the zoom buttons): about the centre of the pane.
    var v = this.view, rect = canvas ? canvas.getBoundingClientRect() : null;
    var sx = rect ? (clientX - rect.left) * this.paneWidth / rect.width : this.paneWidth / 2;
    var sy = rect ? (clientY - rect.top) * this.paneHeight / rect.height : this.paneHeight / 2;
    var ix = (sx - this.paneWidth / 2) / v.zoom + v.cx, iy = (sy - this.paneHeight / 2) / v.zoom + v.cy;
    var zoom = Math.min(Math.max(v.zoom * factor, this.fitZoom / 4), 256);
    // Keep the image point under the pointer where it is.
    v.cx = ix - (sx - this.paneWidth / 2) / zoom;
    v.cy = iy - (sy - this.paneHeight / 2) / zoom;
    v.zoom = zoom;
  };

  Viewer.prototype.changed = function () { this.draw(); this.writeFragment(); };

  Viewer.prototype.bind = function () {
    var self = this, v = this.view, root = this.root;
    root.querySelector('select[data-role="a"]').addEventListener('change', function (e) { v.a = e.target.value; self.changed(); });
    root.querySelector('select[data-role="b"]').addEventListener('change', function (e) { v.b = e.target.value; self.changed(); });
    each(root.querySelectorAll('button[data-mode]'), function (button) {
      button.addEventListener('click', function () { v.mode = button.getAttribute('data-mode'); self.changed(); });
    });
    this.control('exposure').addEventListener('input', function (e) { v.exposure = +e.target.value; self.changed(); });
    this.control('false-colour').addEventListener('change', function (e) { v.falseColour = e.target.checked; self.changed(); });
    this.control('wipe').addEventListener('input', function (e) { v.wipe = +e.target.value; self.changed(); });
    each(root.querySelectorAll('button[data-zoom]'), function (button) {
      button.addEventListener('click', function () {
        var action = button.getAttribute('data-zoom');
        if (action === 'fit') { v.zoom = self.fitZoom; v.cx = self.width / 2; v.cy = self.height / 2; }
        else self.zoomAbout(action === 'in' ? 2 : 0.5, null);
        self.changed();
      });
    });
    var drag = null;
    each(this.canvases, function (canvas) {
      canvas.addEventListener('wheel', function (e) {
        e.preventDefault();
        self.zoomAbout(e.deltaY < 0 ? 2 : 0.5, canvas, e.clientX, e.clientY);
        self.changed();
      }, { passive: false });
      canvas.addEventListener('pointerdown', function (e) {
        var rect = canvas.getBoundingClientRect(), sx = (e.clientX - rect.left) * self.paneWidth / rect.width;
        // Near the wipe line: move the line; elsewhere: pan.
        var onLine = v.mode === 'wipe' && Math.abs(sx - v.wipe * self.paneWidth) < 8;
        drag = { canvas: canvas, wipe: onLine, x: e.clientX, y: e.clientY, cx: v.cx, cy: v.cy, moved: false };
        if (canvas.setPointerCapture && e.pointerId !== undefined) try { canvas.setPointerCapture(e.pointerId); } catch (err) { /* synthetic */ }
      });
      canvas.addEventListener('pointermove', function (e) {
        if (drag && drag.canvas === canvas) {
          var rect = canvas.getBoundingClientRect(), scale = self.paneWidth / rect.width;
          if (Math.abs(e.clientX - drag.x) + Math.abs(e.clientY - drag.y) > 2) drag.moved = true;
          if (drag.wipe) v.wipe = Math.min(Math.max((e.clientX - rect.left) / rect.width, 0), 1);
          else {
            v.cx = drag.cx - (e.clientX - drag.x) * scale / v.zoom;
            v.cy = drag.cy - (e.clientY - drag.y) * scale / v.zoom;
          }
          self.draw();
        }
        if (v.probe) return;  // a pinned pixel keeps its readout
        var p = self.pixelAt(canvas, e.clientX, e.clientY);
        if (p) self.readout(p.x, p.y, false);
      });
      canvas.addEventListener('pointerup', function (e) {
        if (!drag) return;
        if (!drag.moved) {
          // A click pins the pixel's readout (and outlines it); a click on it again unpins.
          var p = self.pixelAt(canvas, e.clientX, e.clientY);
          v.probe = p && !(v.probe && v.probe.x === p.x && v.probe.y === p.y) ? { x: p.x, y: p.y } : null;
        }
        drag = null;
        self.changed();
      });
    });
  };

  window.gibViewers = [];
  each(document.querySelectorAll('.viewer[data-width]'), function (root) {
    window.gibViewers.push(new Viewer(root));
  });
})();
