// The report's self-check, inlined into every page after the image viewer (viewer.js): it marks a
// page whose pictures, image viewers or charts did not render. Plain ES5 so any browser of the
// last decade runs it.
(function () {
  function each(list, f) { Array.prototype.forEach.call(list, f); }
  window.addEventListener('load', function () {
    var problems = [];
    each(document.images, function (img) {
      if (!img.complete || img.naturalWidth === 0) problems.push('image ' + img.getAttribute('src'));
    });
    each(document.querySelectorAll('.viewer'), function (viewer, i) {
      if (viewer.getAttribute('data-viewer-state') !== 'ready') problems.push('image viewer ' + (i + 1));
      ['data-reference-data', 'data-job-data'].forEach(function (attribute) {
        var expected = viewer.getAttribute(attribute);
        if (expected && !(window.gibViewerData && window.gibViewerData[expected]))
          problems.push('viewer data ' + expected);
      });
    });
    each(document.querySelectorAll('svg.chart'), function (svg) {
      var box = svg.getBBox(), rect = svg.getBoundingClientRect();
      if (!(box.width > 0 && box.height > 0 && rect.width > 0 && rect.height > 0))
        problems.push('chart "' + svg.getAttribute('aria-label') + '"');
    });
    var root = document.documentElement;
    // How long the page took from navigation to its load event, for scripts/report-load-time.py
    // and the report benchmark (in real time; a test's virtual time budget makes it virtual).
    root.setAttribute('data-load-ms', String(Math.round(performance.now())));
    if (problems.length === 0) { root.setAttribute('data-report-check', 'ok'); return; }
    root.setAttribute('data-report-check', 'failed: ' + problems.join('; '));
    var banner = document.getElementById('report-check');
    banner.textContent = 'This page is incomplete: ' + problems.join('; ') +
        ' did not render. Keep the whole run directory (jobs/, report/ and index.html) together.';
    banner.hidden = false;
  });
})();
