// Drives the first image viewer of a job page through one scenario, named by
// window.gibViewerScenario (set by the test before the page's scripts): "wheel" (wheel events of
// several deltas and modes), "probe" (the view a #probe fragment opens), "layers" (the signed and
// relative errors, difference, FLIP and false colour with their colour bars, the automatic range
// on and off, a pinned readout), "layout" (the panes' boxes in the window, the full-window button
// and Escape). Leaves its findings on <html data-viewer-test="…"> for
// tests/reports/image_viewer_browser_test.cpp. Loaded after the page's own scripts.
(function () {
  var out = { scenario: window.gibViewerScenario };
  try {
    var viewer = window.gibViewers[0], root = viewer.root;
    var pane = function (id) { return root.querySelector('canvas[data-pane="' + id + '"]'); };
    var view = function () { return JSON.parse(root.getAttribute('data-view')); };
    // The window coordinates of a point of a pane, in the pane's canvas pixels.
    var client = function (canvas, sx, sy) {
      var rect = canvas.getBoundingClientRect();
      return { clientX: rect.left + sx * rect.width / canvas.width, clientY: rect.top + sy * rect.height / canvas.height };
    };
    var pointer = function (canvas, type, sx, sy) {
      var c = client(canvas, sx, sy);
      canvas.dispatchEvent(new PointerEvent(type, { clientX: c.clientX, clientY: c.clientY, bubbles: true, pointerId: 1, isPrimary: true }));
    };
    // Pixels are read from a copy made for reading, so the page's own canvas is never read back.
    var pixel = function (canvas, sx, sy) {
      var copy = document.createElement('canvas');
      copy.width = 1;
      copy.height = 1;
      var ctx = copy.getContext('2d', { willReadFrequently: true });
      ctx.drawImage(canvas, Math.floor(sx), Math.floor(sy), 1, 1, 0, 0, 1, 1);
      var d = ctx.getImageData(0, 0, 1, 1).data;
      return [d[0], d[1], d[2]];
    };
    // The pane point at the centre of image pixel (x, y) under the current view.
    var paneCentreOf = function (canvas, x, y) {
      var v = view();
      return [(x + 0.5 - v.cx) * v.zoom + canvas.width / 2, (y + 0.5 - v.cy) * v.zoom + canvas.height / 2];
    };
    var select = function (role, value) {
      var menu = root.querySelector('select[data-role="' + role + '"]');
      menu.value = value;
      menu.dispatchEvent(new Event('change', { bubbles: true }));
    };
    var rectOf = function (element) {
      var r = element.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width, height: r.height };
    };
    // A colour bar as shown: its range, its ticks and the colour of every column of its strip.
    var bar = function (id) {
      var element = root.querySelector('[data-scale="' + id + '"]');
      if (element.hidden) return { hidden: true };
      var strip = element.querySelector('canvas'), colours = [];
      for (var x = 0; x < strip.width; x++) colours.push(pixel(strip, x, strip.height / 2));
      var ticks = Array.prototype.map.call(element.querySelectorAll('.viewer-tick'), function (tick) {
        return { text: tick.textContent, value: +tick.getAttribute('data-value'), left: parseFloat(tick.style.left) };
      });
      return { layer: element.getAttribute('data-layer'), low: +element.getAttribute('data-low'),
               high: +element.getAttribute('data-high'), ticks: ticks, strip: colours,
               caption: element.querySelector('.viewer-scale-caption').textContent };
    };
    // The colours both panes show at the centres of some image pixels.
    var samples = function (pixels) {
      return pixels.map(function (p) {
        var a = paneCentreOf(pane('a'), p[0], p[1]), b = paneCentreOf(pane('b'), p[0], p[1]);
        return { pixel: p, at: a, a: pixel(pane('a'), a[0], a[1]), b: pixel(pane('b'), b[0], b[1]) };
      });
    };
    var scenario = out.scenario;

    if (scenario === 'wheel') {
      // Each case from the fitted view, at the pane's centre (which stays where it is).
      var canvas = pane('a'), fit = root.querySelector('button[data-zoom="fit"]');
      var wheel = function (deltaY, deltaMode) {
        var c = client(canvas, canvas.width / 2, canvas.height / 2);
        canvas.dispatchEvent(new WheelEvent('wheel', { deltaY: deltaY, deltaMode: deltaMode, clientX: c.clientX,
                                                      clientY: c.clientY, bubbles: true, cancelable: true }));
      };
      out.fit = view().zoom;
      out.cases = [[-10, 0, 1], [-100, 0, 1], [-3, 0, 1], [-3, 1, 1], [50, 0, 1], [-1, 2, 1], [-10, 0, 10]].map(function (c) {
        fit.click();
        for (var k = 0; k < c[2]; k++) wheel(c[0], c[1]);
        return { deltaY: c[0], deltaMode: c[1], events: c[2], zoom: view().zoom };
      });
    } else if (scenario === 'probe') {
      var a = pane('a');
      out.view = view();
      out.pane = [a.width, a.height];
      out.centre = pixel(a, a.width / 2, a.height / 2);
    } else if (scenario === 'layers') {
      var auto = root.querySelector('[data-role="auto-range"]');
      var pixels = [[0, 3], [12, 3], [31, 3], [20, 7], [5, 20], [26, 11]];
      out.pane = [pane('a').width, pane('a').height];
      select('a', 'signed');
      select('b', 'relative');
      out.view = view();
      out.auto = { a: bar('a'), b: bar('b'), samples: samples(pixels) };
      // Pin pixel (20, 7) for the readout.
      var at = paneCentreOf(pane('a'), 20, 7);
      pointer(pane('a'), 'pointerdown', at[0], at[1]);
      pointer(pane('a'), 'pointerup', at[0], at[1]);
      out.readout = root.querySelector('[data-role="readout"]').textContent;
      auto.click();
      out.fixed = { a: bar('a'), b: bar('b'), samples: samples(pixels), view: view() };
      auto.click();
      select('a', 'difference');
      select('b', 'flip');
      out.errors = { a: bar('a'), b: bar('b'), samples: samples(pixels) };
      auto.click();
      out.errorsFixed = { a: bar('a'), b: bar('b'), samples: samples(pixels) };
      // A layer without a bar on the left: the right pane's bar still sits under the right pane.
      select('a', 'image');
      select('b', 'signed');
      out.alignment = { bar: rectOf(root.querySelector('[data-scale="b"]')), pane: rectOf(pane('b')) };
      select('a', 'reference');
      root.querySelector('[data-role="false-colour"]').click();
      var exposure = root.querySelector('[data-role="exposure"]');
      exposure.value = '1';
      exposure.dispatchEvent(new Event('input', { bubbles: true }));
      select('b', 'image');
      out.falseColour = { a: bar('a'), b: bar('b'), samples: samples(pixels), view: view() };
      // The readout's groups when its line is narrow: each stays on one line.
      var readout = root.querySelector('[data-role="readout"]');
      readout.style.width = '120px';
      out.narrowReadout = Array.prototype.map.call(readout.querySelectorAll('.viewer-value'), function (group) {
        return { text: group.textContent, lines: Math.round(group.getBoundingClientRect().height /
                                                            parseFloat(getComputedStyle(group).lineHeight)) };
      });
    } else if (scenario === 'layout') {
      var boxes = function () {
        return { a: rectOf(pane('a')), b: rectOf(pane('b')), aShown: pane('a').offsetParent !== null,
                 bShown: pane('b').offsetParent !== null, full: root.classList.contains('viewer-full'),
                 view: view(), hash: location.hash };
      };
      out.window = { width: document.documentElement.clientWidth, height: window.innerHeight };
      out.page = rectOf(document.body);
      out.side = boxes();
      root.querySelector('button[data-full="b"]').click();
      out.fullB = boxes();
      document.dispatchEvent(new KeyboardEvent('keydown', { key: 'Escape', bubbles: true }));
      out.escaped = boxes();
      root.querySelector('button[data-full="a"]').click();
      out.fullA = boxes();
      root.querySelector('button[data-full="a"]').click();
      out.back = boxes();
    } else {
      out.error = 'unknown scenario ' + scenario;
    }
  } catch (e) {
    out.error = String(e && e.stack || e);
  }
  document.documentElement.setAttribute('data-viewer-test', JSON.stringify(out));
})();
