// The report's script, inlined into every page: the image viewer and the self-check that marks
// a page whose pictures or charts did not render. Plain ES5 so any browser of the last decade
// runs it.
(function () {
  function each(list, f) { Array.prototype.forEach.call(list, f); }
  each(document.querySelectorAll('.viewer'), function (viewer) {
    var chosen = viewer.getAttribute('data-show');
    var partner = { image: 'reference', reference: 'image' };
    function layer(name) { return viewer.querySelector('.layer[data-layer="' + name + '"]'); }
    function show(name) {
      each(viewer.querySelectorAll('.layer'), function (l) { l.hidden = l.getAttribute('data-layer') !== name; });
      each(viewer.querySelectorAll('button[data-layer]'), function (b) {
        b.setAttribute('aria-pressed', String(b.getAttribute('data-layer') === chosen));
      });
      var caption = viewer.querySelector('.viewer-caption');
      if (caption && layer(name)) caption.textContent = layer(name).alt + (name === chosen ? '' : ' (while the pointer is on the image)');
    }
    each(viewer.querySelectorAll('button[data-layer]'), function (b) {
      b.addEventListener('click', function () { chosen = b.getAttribute('data-layer'); show(chosen); });
    });
    var stage = viewer.querySelector('.viewer-stage');
    stage.addEventListener('mouseenter', function () { if (layer(partner[chosen])) show(partner[chosen]); });
    stage.addEventListener('mouseleave', function () { show(chosen); });
    show(chosen);
  });
  window.addEventListener('load', function () {
    var problems = [];
    each(document.images, function (img) {
      if (!img.complete || img.naturalWidth === 0) problems.push('image ' + img.getAttribute('src'));
    });
    each(document.querySelectorAll('.viewer'), function (viewer, i) {
      var shown = 0;
      each(viewer.querySelectorAll('.layer'), function (l) { if (l.offsetParent !== null) shown += 1; });
      if (shown !== 1) problems.push('image viewer ' + (i + 1) + ' shows ' + shown + ' pictures instead of one');
    });
    each(document.querySelectorAll('svg.chart'), function (svg) {
      var box = svg.getBBox(), rect = svg.getBoundingClientRect();
      if (!(box.width > 0 && box.height > 0 && rect.width > 0 && rect.height > 0))
        problems.push('chart "' + svg.getAttribute('aria-label') + '"');
    });
    var root = document.documentElement;
    if (problems.length === 0) { root.setAttribute('data-report-check', 'ok'); return; }
    root.setAttribute('data-report-check', 'failed: ' + problems.join('; '));
    var banner = document.getElementById('report-check');
    banner.textContent = 'This page is incomplete: ' + problems.join('; ') +
        ' did not render. Keep the whole run directory (jobs/, report/ and index.html) together.';
    banner.hidden = false;
  });
})();
