// Drives the first image viewer of a job page the way a person would, with input events (button
// clicks, wheel, pointer drags, range and checkbox input), then reads pixels of the canvas and
// the readout, and leaves everything on <html data-viewer-test="…"> for the test to check
// (tests/reports/image_viewer_browser_test.cpp). Loaded after the page's own scripts.
(function () {
  var out = { steps: [] };
  try {
    var viewer = window.gibViewers[0], root = viewer.root;
    var pane = root.querySelector('canvas[data-pane="a"]');
    var rect = pane.getBoundingClientRect();
    function client(sx, sy) {
      return { clientX: rect.left + sx * rect.width / pane.width, clientY: rect.top + sy * rect.height / pane.height };
    }
    function pointer(type, sx, sy) {
      var c = client(sx, sy);
      pane.dispatchEvent(new PointerEvent(type, { clientX: c.clientX, clientY: c.clientY, bubbles: true, pointerId: 1, isPrimary: true }));
    }
    // Pixels are read from a copy made for reading, so the page's own canvas is never read back.
    function pixel(sx, sy) {
      var copy = document.createElement('canvas');
      copy.width = 1;
      copy.height = 1;
      var ctx = copy.getContext('2d', { willReadFrequently: true });
      ctx.drawImage(pane, sx, sy, 1, 1, 0, 0, 1, 1);
      var d = ctx.getImageData(0, 0, 1, 1).data;
      return [d[0], d[1], d[2]];
    }
    function view() { return JSON.parse(root.getAttribute('data-view')); }
    function record(name) { out.steps.push({ name: name, view: view() }); }
    out.pane = [pane.width, pane.height];
    out.fit = view();

    root.querySelector('button[data-mode="wipe"]').click();
    record('wipe mode');

    var centre = client(pane.width / 2, pane.height / 2);
    pane.dispatchEvent(new WheelEvent('wheel', { deltaY: -100, clientX: centre.clientX, clientY: centre.clientY, bubbles: true, cancelable: true }));
    record('wheel in at the centre');

    pointer('pointerdown', 100, 100);
    pointer('pointermove', 164, 100);
    pointer('pointerup', 164, 100);
    record('drag 64 pixels right');

    var line = view().wipe * pane.width;
    pointer('pointerdown', line, 50);
    pointer('pointermove', 0.75 * pane.width, 50);
    pointer('pointerup', 0.75 * pane.width, 50);
    record('drag the wipe line to 3/4');

    var exposure = root.querySelector('[data-role="exposure"]');
    exposure.value = '1';
    exposure.dispatchEvent(new Event('input', { bubbles: true }));
    record('exposure +1');

    // Canvas pixels (their top left corners) at fractions of the pane, whose size depends on the
    // window.
    function at(fx, fy) { return [Math.floor(fx * pane.width), Math.floor(fy * pane.height)]; }
    out.samples = [at(0.2, 0.52), at(0.88, 0.52), at(0.59, 0.1)].map(function (p) { return { at: p, rgb: pixel(p[0], p[1]) }; });

    out.hover = at(0.59, 0.52);
    pointer('pointermove', out.hover[0], out.hover[1]);
    out.readout = root.querySelector('[data-role="readout"]').textContent;

    var falseColour = root.querySelector('[data-role="false-colour"]');
    falseColour.click();
    record('false colour');
    out.false_samples = [at(0.2, 0.52)].map(function (p) { return { at: p, rgb: pixel(p[0], p[1]) }; });
    out.hash = location.hash;
  } catch (e) {
    out.error = String(e && e.stack || e);
  }
  document.documentElement.setAttribute('data-viewer-test', JSON.stringify(out));
})();
