// The page checks its own images on load (tests/report/check_in_browser.cmake reads the result).
var raylabErrors = [];
window.addEventListener('error', function (e) {
  if (!(e.target instanceof HTMLImageElement)) raylabErrors.push(String(e.message));
}, true);
window.addEventListener('load', function () {
  var broken = [];
  for (var k = 0; k < document.images.length; ++k) {
    var img = document.images[k];
    if (!img.complete || img.naturalWidth === 0) broken.push(img.getAttribute('src'));
  }
  var ok = broken.length === 0 && raylabErrors.length === 0 && document.images.length > 0;
  document.getElementById('image-check').textContent = 'image check: ' + (ok ? 'ok' : 'FAILED') + ', ' +
    document.images.length + ' images, broken: [' + broken.join(', ') + '], errors: [' +
    raylabErrors.join(' | ') + ']';
});
