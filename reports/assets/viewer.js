// The image viewer of a job page (reports/image_viewer.cpp writes its markup): two panes side by
// side or one pane with a wipe between them, each showing a layer (reference, image, difference,
// signed difference, relative error, FLIP, the reference's standard error); zoom and pan shared by
// both panes, nearest-neighbour when magnified; panes sized to the window, and a pane can fill the
// window; exposure in stops and a false-colour toggle; error layers through a colour map with a
// colour bar of their true values, their range automatic (tev's "normalise") unless switched off;
// the values of every layer at the pixel under the pointer. Layers come from the job's viewer data
// (linear half floats registered in window.gibViewerData by scripts beside the page,
// image/viewer_data.h), so exposure, error layers and readout work on the real values; a run
// without that data falls back to its PNGs (display only).
// The view is kept in the address's #fragment (a=, b=, mode=, wipe=, zoom=, cx=, cy=, exposure=,
// false=, auto=, full=a|b, probe=x,y), so a view can be linked to and a screenshot scripted; a
// probe without cx/cy centres the view on it. Plain ES5.
(function () {
  'use strict';
  function each(list, f) { Array.prototype.forEach.call(list, f); }
  function clamp(v, low, high) { return Math.min(Math.max(v, low), high); }

  // ε of relMSE and of the relative error layer (metrics/image_metrics.h, kRelativeEpsilon).
  var kRelativeEpsilon = 0.01;
  // A wheel zooms by 2× per step, in proportion to its delta: one notch of a mouse is one step
  // (Chrome reports it as 100 pixels, Firefox as 3 lines, page mode as one page); a trackpad's
  // stream of small deltas zooms smoothly. One event zooms at most kMaxWheelSteps steps.
  var kWheelPixelsPerStep = 100, kWheelLinesPerStep = 3, kMaxWheelSteps = 4;
  // Pane layout, in CSS pixels: the margin kept from the window's sides when the viewer widens past
  // the page's text column, the gap between the panes (report.css, .viewer-stage), the height kept
  // below the panes for the colour bars and the readout, the least height of a pane.
  var kWindowMargin = 16, kPaneGap = 8, kBelowPanes = 150, kMinPaneHeight = 160;

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
  function srgbByte(v) { return srgbTable[Math.round(clamp(v, 0, 1) * 4096)]; }

  function hexBytes(hex) {
    var bytes = new Uint8ClampedArray(hex.length >> 1);
    for (var i = 0; i < bytes.length; i++) bytes[i] = parseInt(hex.substr(2 * i, 2), 16);
    return bytes;
  }

  // The one number format of the readout and the colour bars' captions: 4 significant digits,
  // with an exponent outside [1e-3, 1e4).
  function formatValue(v) {
    if (!isFinite(v)) return String(v);
    if (v === 0) return '0';
    var a = Math.abs(v);
    return a >= 1e4 || a < 1e-3 ? v.toExponential(3) : v.toPrecision(4);
  }

  // Rec. 709 luminance of linear RGB (image/image.h, rec709Luminance).
  function luminance(rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

  // Colour maps are 256 sRGB byte triples, entry i for t = i / 255. Magma comes from the page
  // (the PNGs' map, image/false_color.h); the diverging map of the signed difference is
  // ColorBrewer's RdBu (11 classes) from blue (negative: the image darker than the reference)
  // through white (0) to red, linear in sRGB between its stops.
  var kDivergingStops = ['053061', '2166ac', '4393c3', '92c5de', 'd1e5f0', 'f7f7f7',
                         'fddbc7', 'f4a582', 'd6604d', 'b2182b', '67001f'];
  function divergingMap() {
    var stops = kDivergingStops.map(hexBytes), table = new Uint8ClampedArray(768), last = stops.length - 1;
    for (var i = 0; i < 256; i++) {
      var s = i / 255 * last, k = Math.min(Math.floor(s), last - 1), f = s - k;
      for (var c = 0; c < 3; c++) table[3 * i + c] = Math.round(stops[k][c] + (stops[k + 1][c] - stops[k][c]) * f);
    }
    return table;
  }

  // Writes the colour of t (clamped to [0, 1]) under a colour map into RGBA bytes at `o`: the
  // one mapping of the panes and of the colour bars.
  function paintMapped(table, t, out, o) {
    var m = 3 * Math.round(clamp(t, 0, 1) * 255);
    out[o] = table[m]; out[o + 1] = table[m + 1]; out[o + 2] = table[m + 2]; out[o + 3] = 255;
  }

  // Error layers: one value per pixel, shown through a colour map with a colour bar. `value` makes
  // it from the image's and the reference's RGB at a pixel; `layer` reads a one-channel layer of
  // the viewer data instead. `symmetric`: the range is ±m around 0. `high`: the top of the range
  // with the automatic range off (else 2^-exposure). The differences are of luminance, as the
  // report's difference PNG (metrics::absoluteLuminanceDifference).
  var kErrors = {
    difference: { map: 'magma', what: '|ΔL|, L the luminance',
                  value: function (t, r) { return Math.abs(luminance(t) - luminance(r)); } },
    signed: { map: 'diverging', symmetric: true, what: 'ΔL = L(image) − L(reference), L the luminance; blue: darker, red: brighter',
              value: function (t, r) { return luminance(t) - luminance(r); } },
    relative: { map: 'magma', what: '|ΔL| / (L(reference) + ' + kRelativeEpsilon + ')',
                value: function (t, r) {
                  var l = luminance(r);
                  return Math.abs(luminance(t) - l) / (Math.abs(l) + kRelativeEpsilon);
                } },
    flip: { map: 'magma', layer: 'flip', high: 1, what: 'FLIP error' }  // in [0, 1] by construction
  };

  // Tick values of a colour bar over [low, high]: the multiples of a step of 1, 2 or 5 × 10^k,
  // about five of them.
  function tickValues(low, high) {
    var raw = (high - low) / 5, power = Math.pow(10, Math.floor(Math.log(raw) / Math.LN10)), step = 10 * power;
    [5, 2, 1].forEach(function (m) { if (m * power >= raw) step = m * power; });  // the least that is ≥ raw
    var values = [];
    for (var k = Math.ceil(low / step - 1e-9); k <= Math.floor(high / step + 1e-9); k++) values.push(k * step);
    return { step: step, values: values };
  }
  // A tick's label: as many decimals as the step has (0.05, 0.10, 0.15), an exponent for tiny or
  // huge steps.
  function formatTick(value, step) {
    if (Math.abs(value) < step * 1e-6) return '0';
    if (step < 1e-3 || step >= 1e4) return (+value.toPrecision(3)).toExponential();
    return value.toFixed(Math.max(0, -Math.floor(Math.log(step) / Math.LN10 + 1e-9)));
  }

  // Zoom steps of a wheel event (negative deltaY: towards the viewer, zoom in).
  function wheelSteps(e) {
    var perStep = e.deltaMode === 1 ? kWheelLinesPerStep : e.deltaMode === 2 ? 1 : kWheelPixelsPerStep;
    return clamp(-e.deltaY / perStep, -kMaxWheelSteps, kMaxWheelSteps);
  }

  function appendElement(parent, tag, className, text) {
    var element = document.createElement(tag);
    if (className) element.className = className;
    if (text !== undefined) element.textContent = text;
    parent.appendChild(element);
    return element;
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
    this.maps = { magma: hexBytes(root.getAttribute('data-magma')), diverging: divergingMap() };
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
    this.fields = {};     // error layers' values, made on first use
    this.autoHighs = {};  // and their automatic ranges
    this.pngs = {};
    each(root.querySelectorAll('img.layer'), function (img) { self.pngs[img.getAttribute('data-layer')] = img; });
    this.names = [];
    this.labels = {};
    each(root.querySelector('select[data-role="a"]').options, function (o) {
      self.names.push(o.value);
      self.labels[o.value] = o.textContent;
    });
    this.view = { a: root.getAttribute('data-a'), b: root.getAttribute('data-b'), mode: 'side', wipe: 0.5,
                  zoom: null, cx: this.width / 2, cy: this.height / 2, exposure: 0, falseColour: false,
                  autoRange: true, full: null, probe: null };
    this.fitZoom = null;
    this.cache = {};
    this.canvases = root.querySelectorAll('canvas[data-pane]');
    this.control = function (role) { return root.querySelector('[data-role="' + role + '"]'); };
    if (!this.linear)
      ['exposure', 'false-colour', 'auto-range'].forEach(function (role) { self.control(role).disabled = true; });
    var fragment = parseFragment();
    this.applyFragment(fragment);
    this.bind();
    this.layout();
    // The PNGs of a run without linear data decode after this script ran: draw again once they
    // have (before the page's self-check, which listens to the same event later).
    if (!this.linear) window.addEventListener('load', function () { self.cache = {}; self.draw(); });
    root.setAttribute('data-viewer-state', 'ready');
    // A link to a view shows the view, not the top of the page ("focus=1": the viewer alone,
    // for a screenshot or a large screen).
    if (fragment.focus === '1') document.body.className += ' viewer-focus';
    else if (fragment.mode || fragment.zoom || fragment.probe) {
      root.scrollIntoView();
      // Again once the pictures above the viewer have decoded and moved it.
      window.addEventListener('load', function () { root.scrollIntoView(); });
    }
  }

  Viewer.prototype.applyFragment = function (f) {
    var v = this.view, names = this.names;
    if (names.indexOf(f.a) >= 0) v.a = f.a;
    if (names.indexOf(f.b) >= 0) v.b = f.b;
    if (f.mode === 'wipe' || f.mode === 'side') v.mode = f.mode;
    if (isFinite(+f.wipe) && f.wipe !== undefined) v.wipe = clamp(+f.wipe, 0, 1);
    if (+f.zoom > 0) v.zoom = Math.min(+f.zoom, 256);  // layout() clamps it below, at a quarter of the fit
    if (this.linear && f.exposure !== undefined && isFinite(+f.exposure)) v.exposure = clamp(+f.exposure, -20, 20);
    if (this.linear && f['false'] !== undefined) v.falseColour = f['false'] === '1';
    if (this.linear && f.auto !== undefined) v.autoRange = f.auto !== '0';
    if (f.full === 'a' || f.full === 'b') v.full = f.full;
    if (f.probe) {
      var p = f.probe.split(',');
      if (p.length === 2 && isFinite(+p[0]) && isFinite(+p[1])) v.probe = { x: Math.floor(+p[0]), y: Math.floor(+p[1]) };
    }
    // A probe without a centre: the view centred on the probe pixel, so a zoomed link shows it.
    if (v.probe) { v.cx = v.probe.x + 0.5; v.cy = v.probe.y + 0.5; }
    if (f.cx !== undefined && isFinite(+f.cx)) v.cx = +f.cx;
    if (f.cy !== undefined && isFinite(+f.cy)) v.cy = +f.cy;
  };

  Viewer.prototype.writeFragment = function () {
    var v = this.view;
    var parts = ['a=' + v.a, 'b=' + v.b, 'mode=' + v.mode, 'wipe=' + v.wipe.toFixed(3), 'zoom=' + v.zoom,
                 'cx=' + v.cx.toFixed(2), 'cy=' + v.cy.toFixed(2), 'exposure=' + v.exposure,
                 'false=' + (v.falseColour ? 1 : 0), 'auto=' + (v.autoRange ? 1 : 0)];
    if (v.full) parts.push('full=' + v.full);
    if (v.probe) parts.push('probe=' + v.probe.x + ',' + v.probe.y);
    try { history.replaceState(null, '', '#' + parts.join('&')); } catch (e) { /* some file:// pages refuse */ }
  };

  // Whether a layer has linear values (else it is its PNG, or nothing).
  Viewer.prototype.hasValues = function (name) {
    return kErrors[name] ? !!this.field(name) : !!this.layers[name];
  };

  // The values of an error layer, one per pixel (row 0 at the top), or null without the data.
  Viewer.prototype.field = function (name) {
    if (name in this.fields) return this.fields[name];
    var error = kErrors[name], field = null, n = this.width * this.height, i;
    var source = error.layer && this.layers[error.layer];
    if (source) {
      field = new Float64Array(n);
      for (i = 0; i < n; i++) field[i] = source.values[i * source.channels];
    } else if (!error.layer && this.layers.image && this.layers.reference) {
      field = new Float64Array(n);
      for (i = 0; i < n; i++) {
        var x = i % this.width, y = (i - x) / this.width;
        field[i] = error.value(this.rgb('image', x, y), this.rgb('reference', x, y));
      }
    }
    return (this.fields[name] = field);
  };

  // The RGB of a colour layer at a pixel (one channel repeated).
  Viewer.prototype.rgb = function (name, x, y) {
    var layer = this.layers[name], o = (y * layer.width + x) * layer.channels, d = layer.values;
    return layer.channels >= 3 ? [d[o], d[o + 1], d[o + 2]] : [d[o], d[o], d[o]];
  };

  // The linear values of a layer at a pixel: RGB, or one value for an error layer.
  Viewer.prototype.valuesAt = function (name, x, y) {
    return kErrors[name] ? [this.field(name)[y * this.width + x]] : this.rgb(name, x, y);
  };

  // tev's "normalise", made robust to fireflies: the 99th percentile of the layer's magnitudes
  // (the rule of the report's error-map PNGs, metrics/error_map_display.cpp), so that one firefly
  // does not leave the rest of the map dark; 1 where that is 0.
  Viewer.prototype.autoHigh = function (name) {
    if (name in this.autoHighs) return this.autoHighs[name];
    var field = this.field(name), magnitudes = new Float64Array(field.length), n = 0;
    for (var i = 0; i < field.length; i++) if (isFinite(field[i])) magnitudes[n++] = Math.abs(field[i]);
    var sorted = magnitudes.subarray(0, n).sort(), high = n ? sorted[Math.floor(0.99 * (n - 1))] : 0;
    return (this.autoHighs[name] = high > 0 ? high : 1);
  };

  // What a layer's colour map spans: { low, high, map, what, how }, or null where the layer is
  // shown in its own colours (a colour layer without false colour, a layer without linear data).
  Viewer.prototype.range = function (name) {
    var v = this.view, error = kErrors[name], scale = Math.pow(2, -v.exposure);
    if (!this.hasValues(name)) return null;
    var exposure = 'exposure ' + (v.exposure >= 0 ? '+' : '') + v.exposure + ' EV';
    if (!error)
      return v.falseColour ? { low: 0, high: scale, map: 'magma', what: 'luminance', how: exposure + ':' } : null;
    var high = v.autoRange ? this.autoHigh(name) : error.high || scale;
    var how = v.autoRange ? 'auto range' : error.high ? 'full range' : exposure + ':';
    return { low: error.symmetric ? -high : 0, high: high, map: error.map, what: error.what, how: how };
  };

  // The layer at its own resolution, through exposure and the display transform, or through its
  // colour map, as a canvas; cached per setting.
  Viewer.prototype.layerCanvas = function (name) {
    var v = this.view, linear = this.hasValues(name), range = this.range(name);
    var key = name + (linear ? '|' + v.exposure + '|' + (range ? range.low + ',' + range.high : 'rgb') : '');
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
    var scale = Math.pow(2, v.exposure), field = kErrors[name] ? this.field(name) : null;
    var table = range && this.maps[range.map], span = range ? range.high - range.low : 1;
    for (var y = 0; y < this.height; y++)
      for (var x = 0; x < this.width; x++) {
        var i = y * this.width + x, o = 4 * i;
        var rgb = field ? null : this.rgb(name, x, y);
        // An error layer's value, or a colour layer's luminance in false colour.
        var s = field ? field[i] : range ? luminance(rgb) : 0;
        if (!(field ? isFinite(s) : isFinite(rgb[0]) && isFinite(rgb[1]) && isFinite(rgb[2]))) {
          out[o] = 255; out[o + 1] = 0; out[o + 2] = 255; out[o + 3] = 255;  // as the PNGs: a renderer bug shows
        } else if (range) {
          paintMapped(table, (s - range.low) / span, out, o);
        } else {
          out[o] = srgbByte(rgb[0] * scale); out[o + 1] = srgbByte(rgb[1] * scale); out[o + 2] = srgbByte(rgb[2] * scale);
          out[o + 3] = 255;
        }
      }
    ctx.putImageData(pixels, 0, 0);
    return (this.cache[key] = canvas);
  };

  // The colour bar of a pane's layer: its map over the layer's range, ticks with their values,
  // and a caption; hidden where the layer is shown in its own colours.
  Viewer.prototype.drawScale = function (pane, name, shown) {
    var bar = this.root.querySelector('[data-scale="' + pane + '"]'), range = shown ? this.range(name) : null;
    var width = this.paneWidth;
    // As wide as its pane even when empty: side by side, the right pane's bar stays under it.
    bar.style.width = width + 'px';
    bar.hidden = !range;
    if (!range) return;
    bar.setAttribute('data-layer', name);
    bar.setAttribute('data-low', String(range.low));
    bar.setAttribute('data-high', String(range.high));
    bar.textContent = '';
    var side = this.view.mode === 'wipe' ? (pane === 'a' ? 'Left: ' : 'Right: ') : '';
    // The range first: where the caption is cut short, what the values are goes.
    appendElement(bar, 'div', 'viewer-scale-caption', side + this.labels[name] + ' · ' + range.how + ' ' +
                  formatValue(range.low) + ' to ' + formatValue(range.high) + ' · ' + range.what);
    var strip = appendElement(bar, 'canvas', 'viewer-scale-strip');
    strip.width = width;
    strip.height = 12;
    var ctx = strip.getContext('2d'), pixels = ctx.createImageData(width, strip.height), table = this.maps[range.map];
    for (var x = 0; x < width; x++)
      for (var y = 0; y < strip.height; y++) paintMapped(table, (x + 0.5) / width, pixels.data, 4 * (y * width + x));
    ctx.putImageData(pixels, 0, 0);
    var ticks = appendElement(bar, 'div', 'viewer-ticks'), span = range.high - range.low, t = tickValues(range.low, range.high);
    t.values.forEach(function (value) {
      var tick = appendElement(ticks, 'span', 'viewer-tick', formatTick(value, t.step));
      tick.style.left = (100 * (value - range.low) / span) + '%';
      tick.setAttribute('data-value', String(value));
    });
  };

  Viewer.prototype.drawLayer = function (ctx, name) {
    var v = this.view;
    ctx.save();
    ctx.setTransform(v.zoom, 0, 0, v.zoom, this.paneWidth / 2 - v.cx * v.zoom, this.paneHeight / 2 - v.cy * v.zoom);
    // Magnified by 2 or more: every pixel a sharp square; below, a smooth resampling.
    ctx.imageSmoothingEnabled = v.zoom < 2 && v.zoom !== 1;
    ctx.drawImage(this.layerCanvas(name), 0, 0);
    if (v.probe) {
      ctx.lineWidth = 2 / v.zoom;
      ctx.strokeStyle = '#00e5ff';
      ctx.strokeRect(v.probe.x, v.probe.y, 1, 1);
    }
    ctx.restore();
  };

  // Which panes show: both side by side; in wipe mode pane A (with both layers); in full-window
  // mode the chosen one.
  Viewer.prototype.paneShown = function (pane) {
    var v = this.view;
    return v.mode === 'wipe' ? pane === 'a' : !v.full || v.full === pane;
  };

  // The panes' size from the room the window gives them: side by side, two panes share the
  // window's width (the viewer widens past the page's text column on a wide screen); in
  // full-window mode the shown pane fills the window. The image is enlarged by a whole factor
  // from 2× up (even, sharp pixels) or fitted exactly below that. The zoom keeps what it showed.
  Viewer.prototype.layout = function () {
    var root = this.root, v = this.view, full = !!v.full;
    root.classList.toggle('viewer-full', full);
    root.style.width = '';
    root.style.marginLeft = '';
    var style = getComputedStyle(root), boxWidth;
    if (full) {
      boxWidth = root.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight);
    } else {
      var column = root.getBoundingClientRect();
      var width = Math.max(column.width, document.documentElement.clientWidth - 2 * kWindowMargin);
      if (width > column.width) {
        root.style.width = width + 'px';
        root.style.marginLeft = (kWindowMargin - column.left - window.pageXOffset) + 'px';
      }
      boxWidth = (width - kPaneGap) / 2;
    }
    var tools = root.querySelector('.viewer-tools');
    var boxHeight = Math.max(window.innerHeight - tools.offsetHeight - kBelowPanes -
                             (full ? parseFloat(style.paddingTop) + parseFloat(style.paddingBottom) : 0), kMinPaneHeight);
    var fit = Math.min(boxWidth / this.width, boxHeight / this.height);
    if (fit >= 2) fit = Math.floor(fit);
    this.paneWidth = Math.max(1, Math.floor(full ? boxWidth : this.width * fit));
    this.paneHeight = Math.max(1, Math.floor(full ? boxHeight : this.height * fit));
    if (v.zoom === null) v.zoom = fit;
    else if (this.fitZoom) v.zoom *= fit / this.fitZoom;
    v.zoom = clamp(v.zoom, fit / 4, 256);
    this.fitZoom = fit;
    var self = this;
    each(this.canvases, function (canvas) {
      canvas.width = self.paneWidth;
      canvas.height = self.paneHeight;
      canvas.style.width = self.paneWidth + 'px';
      canvas.style.height = self.paneHeight + 'px';
    });
    this.control('wipe').style.width = this.paneWidth + 'px';
    this.draw();
  };

  Viewer.prototype.draw = function () {
    var v = this.view, root = this.root, self = this;
    var b = this.canvases[1], a = this.canvases[0], wipe = v.mode === 'wipe';
    each(root.querySelectorAll('[data-pane-box]'), function (box) { box.hidden = !self.paneShown(box.getAttribute('data-pane-box')); });
    each(root.querySelectorAll('button[data-full]'), function (button) {
      button.setAttribute('aria-pressed', String(!!v.full && self.paneShown(button.getAttribute('data-full'))));
    });
    root.setAttribute('data-mode', v.mode);
    this.control('wipe').hidden = !wipe;
    var ctx = a.getContext('2d');
    ctx.fillStyle = '#808080';
    ctx.fillRect(0, 0, a.width, a.height);
    if (wipe) {
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
    this.drawScale('a', v.a, this.paneShown('a'));
    this.drawScale('b', v.b, wipe || this.paneShown('b'));
    root.querySelector('select[data-role="a"]').value = v.a;
    root.querySelector('select[data-role="b"]').value = v.b;
    each(root.querySelectorAll('button[data-mode]'), function (button) {
      button.setAttribute('aria-pressed', String(button.getAttribute('data-mode') === v.mode));
    });
    this.control('exposure').value = v.exposure;
    this.control('exposure-value').textContent = (v.exposure >= 0 ? '+' : '') + v.exposure + ' EV';
    this.control('false-colour').checked = v.falseColour;
    this.control('auto-range').checked = v.autoRange;
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

  // The values of every layer at a pixel, one group per layer ("Reference R 0.5000 G 0.2500
  // B 0.1250", "Signed difference 0.1250"), each kept on one line (report.css).
  Viewer.prototype.readout = function (x, y, pinned) {
    var self = this, box = this.control('readout');
    box.textContent = '';
    appendElement(box, 'span', 'viewer-pixel', 'pixel (' + x + ', ' + y + ')' + (pinned ? ' pinned' : ''));
    if (!this.linear) {
      appendElement(box, 'span', 'viewer-value', ' (no linear data in this run: values are not available)');
      return;
    }
    this.names.forEach(function (name) {
      if (!self.hasValues(name)) return;
      var values = self.valuesAt(name, x, y);
      box.appendChild(document.createTextNode(' '));
      var group = appendElement(box, 'span', 'viewer-value');
      appendElement(group, 'b', '', self.labels[name]);
      values.forEach(function (value, c) {
        if (values.length > 1) appendElement(group, 'i', '', ' ' + 'RGB'.charAt(c));
        group.appendChild(document.createTextNode(' '));
        appendElement(group, 'span', 'viewer-number', formatValue(value));
      });
    });
  };

  Viewer.prototype.zoomAbout = function (factor, canvas, clientX, clientY) {
    // Without a canvas (the zoom buttons): about the centre of the pane.
    var v = this.view, rect = canvas ? canvas.getBoundingClientRect() : null;
    var sx = rect ? (clientX - rect.left) * this.paneWidth / rect.width : this.paneWidth / 2;
    var sy = rect ? (clientY - rect.top) * this.paneHeight / rect.height : this.paneHeight / 2;
    var ix = (sx - this.paneWidth / 2) / v.zoom + v.cx, iy = (sy - this.paneHeight / 2) / v.zoom + v.cy;
    var zoom = clamp(v.zoom * factor, this.fitZoom / 4, 256);
    // Keep the image point under the pointer where it is.
    v.cx = ix - (sx - this.paneWidth / 2) / zoom;
    v.cy = iy - (sy - this.paneHeight / 2) / zoom;
    v.zoom = zoom;
  };

  Viewer.prototype.changed = function () { this.draw(); this.writeFragment(); };

  // Into or out of full-window mode: the panes change size, so lay them out again.
  Viewer.prototype.setFull = function (pane) {
    this.view.full = pane;
    this.layout();
    this.writeFragment();
  };

  Viewer.prototype.bind = function () {
    var self = this, v = this.view, root = this.root;
    root.querySelector('select[data-role="a"]').addEventListener('change', function (e) { v.a = e.target.value; self.changed(); });
    root.querySelector('select[data-role="b"]').addEventListener('change', function (e) { v.b = e.target.value; self.changed(); });
    each(root.querySelectorAll('button[data-mode]'), function (button) {
      button.addEventListener('click', function () { v.mode = button.getAttribute('data-mode'); self.changed(); });
    });
    this.control('exposure').addEventListener('input', function (e) { v.exposure = +e.target.value; self.changed(); });
    this.control('false-colour').addEventListener('change', function (e) { v.falseColour = e.target.checked; self.changed(); });
    this.control('auto-range').addEventListener('change', function (e) { v.autoRange = e.target.checked; self.changed(); });
    this.control('wipe').addEventListener('input', function (e) { v.wipe = +e.target.value; self.changed(); });
    each(root.querySelectorAll('button[data-zoom]'), function (button) {
      button.addEventListener('click', function () {
        var action = button.getAttribute('data-zoom');
        if (action === 'fit') { v.zoom = self.fitZoom; v.cx = self.width / 2; v.cy = self.height / 2; }
        else self.zoomAbout(action === 'in' ? 2 : 0.5, null);
        self.changed();
      });
    });
    each(root.querySelectorAll('button[data-full]'), function (button) {
      button.addEventListener('click', function () { self.setFull(v.full ? null : button.getAttribute('data-full')); });
    });
    document.addEventListener('keydown', function (e) { if (e.key === 'Escape' && v.full) self.setFull(null); });
    window.addEventListener('resize', function () { self.layout(); });
    var drag = null;
    each(this.canvases, function (canvas) {
      canvas.addEventListener('wheel', function (e) {
        e.preventDefault();
        self.zoomAbout(Math.pow(2, wheelSteps(e)), canvas, e.clientX, e.clientY);
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
          if (drag.wipe) v.wipe = clamp((e.clientX - rect.left) / rect.width, 0, 1);
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
