// The report's stylesheet and script, inlined into every report so it works from a file share or
// a CI artifact without network access. Nothing here may reference a URL.

namespace taa::report::detail {

const char* const kReportCss = R"CSS(
:root { --pass: #1e7d32; --fail: #c62828; --stale: #b26a00; --nogolden: #546e7a;
  --error: #6a1b9a; --tol: #00796b; --line: #d8d8d4; --mono: ui-monospace, "DejaVu Sans Mono",
  Menlo, Consolas, monospace; }
* { box-sizing: border-box; }
body { margin: 0; padding: 12px 20px 40px; background: #f4f4f1; color: #1b1b1b;
  font: 14px/1.4 system-ui, "DejaVu Sans", sans-serif; }
h1 { font-size: 20px; margin: 4px 0 8px; }
h2 { font-size: 17px; margin: 0 0 6px; display: flex; gap: 8px; align-items: baseline;
  flex-wrap: wrap; }
h3 { font-size: 14px; margin: 14px 0 6px; border-bottom: 1px solid var(--line); }
h4 { font-size: 13px; margin: 0 0 6px; }
code, pre, .mono, td.num { font-family: var(--mono); font-size: 12px; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
header.run, nav.toc, section.case, section.extra { background: #fff; border: 1px solid var(--line);
  border-radius: 6px; padding: 10px 14px; margin: 0 0 14px; }
section.case { border-left-width: 6px; }
section.case.st-pass { border-left-color: var(--pass); }
section.case.st-fail { border-left-color: var(--fail); }
section.case.st-stale { border-left-color: var(--stale); }
section.case.st-no_golden { border-left-color: var(--nogolden); }
section.case.st-error { border-left-color: var(--error); }
.kv { display: grid; grid-template-columns: max-content 1fr; gap: 2px 12px; margin: 0; }
.kv dt { color: #666; } .kv dd { margin: 0; font-family: var(--mono); font-size: 12px;
  overflow-wrap: anywhere; }
.badge { display: inline-block; padding: 1px 7px; border-radius: 3px; color: #fff;
  font: bold 11px/1.5 var(--mono); letter-spacing: .03em; white-space: nowrap; }
.badge.st-pass, .badge.st-exact { background: var(--pass); }
.badge.st-within_tolerance { background: var(--tol); }
.badge.st-fail, .badge.st-failed { background: var(--fail); }
.badge.st-stale { background: var(--stale); }
.badge.st-no_golden, .badge.st-missing_golden { background: var(--nogolden); }
.badge.st-error { background: var(--error); }
.summary { display: flex; gap: 14px; flex-wrap: wrap; margin: 8px 0 0; }
.summary span { font-family: var(--mono); }
table { border-collapse: collapse; margin: 4px 0; }
th, td { border: 1px solid var(--line); padding: 2px 7px; vertical-align: top; text-align: left; }
.extra-table td:last-child { overflow-wrap: anywhere; }
th { background: #f0f0ec; font-weight: 600; font-size: 12px; }
tr.bad td { background: #fdecea; }
td.bad { color: var(--fail); font-weight: bold; }
td.bad::after { content: " !"; }
.file { color: #666; font: 12px var(--mono); }
.desc { margin: 2px 0 6px; }
.msg { white-space: pre-wrap; font-family: var(--mono); font-size: 12px; background: #fff8e1;
  border: 1px solid #f0dca0; padding: 4px 8px; margin: 4px 0; }
.bless { display: flex; gap: 6px; align-items: center; margin: 4px 0; }
.bless code { background: #f0f0ec; padding: 3px 6px; border: 1px solid var(--line);
  overflow-wrap: anywhere; user-select: all; }
button { font: 12px var(--mono); padding: 1px 8px; cursor: pointer; }
button[aria-pressed="true"] { background: #333; color: #fff; }
.failures { margin: 2px 0 6px; padding-left: 20px; color: var(--fail); font: 12px var(--mono); }
.frame { border-top: 1px dashed var(--line); padding: 8px 0; }
.row { display: flex; gap: 10px; flex-wrap: wrap; align-items: flex-start; }
figure { margin: 0; min-width: 0; }
figcaption { font: 11px var(--mono); color: #555; margin-bottom: 2px; }
.triptych figure { flex: 0 1 auto; max-width: calc(33.3% - 7px); }
.triptych img { max-width: 100%; }
.triptych img.fit { image-rendering: auto; }
.ab.small .tag { display: none; }
img { image-rendering: pixelated; display: block; background: #888; }
.missing { display: flex; align-items: center; justify-content: center; min-width: 160px;
  min-height: 60px; padding: 6px; border: 1px dashed #aaa; color: #777; font: 12px var(--mono);
  background: repeating-linear-gradient(45deg, #fafafa, #fafafa 6px, #f0f0f0 6px, #f0f0f0 12px); }
.ab-tools { display: flex; gap: 6px; align-items: center; font: 12px var(--mono);
  margin: 8px 0 3px; flex-wrap: wrap; }
.ab-scroll { display: inline-block; max-width: 100%; max-height: 80vh; overflow: auto;
  border: 1px solid var(--line); vertical-align: top; }
.split { position: relative; display: inline-block; line-height: 0; cursor: ew-resize;
  touch-action: none; user-select: none; outline: none; }
.split:focus-visible { box-shadow: 0 0 0 2px #2f6fdb; }
.split img { max-width: none; pointer-events: none; }
.split .ab-golden { position: absolute; left: 0; top: 0; width: 100%; height: 100%;
  clip-path: inset(0 50% 0 0); }
.split .divider { position: absolute; top: 0; bottom: 0; left: 50%; width: 0;
  border-left: 2px solid #fff; box-shadow: 0 0 0 1px #000; pointer-events: none; }
.split .divider::after { content: ""; position: absolute; top: 50%; left: -7px; width: 12px;
  height: 24px; margin-top: -12px; background: #fff; border: 1px solid #000; border-radius: 3px; }
.split .tag { position: absolute; top: 3px; padding: 0 4px; background: rgba(0,0,0,.6);
  color: #fff; font: 11px/1.5 var(--mono); pointer-events: none; }
.split .tag.l { left: 3px; } .split .tag.r { right: 3px; }
.crops figure img { border: 1px solid #444; }
.plots { display: flex; gap: 10px; flex-wrap: wrap; }
svg.plot { border: 1px solid var(--line); max-width: 100%; height: auto; }
details > summary { cursor: pointer; color: #444; margin-top: 10px; }
pre.log { max-height: 320px; overflow: auto; background: #f7f7f5; border: 1px solid var(--line);
  padding: 6px; margin: 4px 0; }
.muted { color: #777; }
nav.toc td a { font-family: var(--mono); }
[hidden] { display: none !important; }
/* A long message (a stale case quotes its bless reason) stays a few lines; the case has it all. */
.toc-msg { max-width: 46em; display: -webkit-box; -webkit-box-orient: vertical;
  -webkit-line-clamp: 3; overflow: hidden; }
.thumbs { display: flex; gap: 4px; align-items: flex-end; text-decoration: none; color: inherit; }
.thumbs figcaption { font-size: 10px; margin: 0; white-space: nowrap; }
.thumbs-frame { font: 11px var(--mono); color: #555; align-self: center; white-space: nowrap; }
img.thumb { height: 64px; width: auto; max-width: 144px; image-rendering: auto; }
.thumb-none { display: flex; align-items: center; justify-content: center; height: 64px;
  width: 64px; border: 1px dashed #aaa; color: #777; font: 11px var(--mono); }
.bless-from { margin-top: 8px; }
.bless-fields { display: flex; gap: 6px 16px; flex-wrap: wrap; font: 12px var(--mono); }
.bless-fields input { font: 12px var(--mono); padding: 2px 4px; }
#bless-dir { width: 30em; } #bless-reason { width: 40em; }
.bless-hint { color: #777; font: 12px var(--mono); }
)CSS";

// Plain ES2017, no modules: it must run from file:// in any recent browser. The load handler
// records whether every image decoded (data-images-loaded="ok/total") and whether the page
// rendered (data-render-ok) on <body>, which the headless-browser test reads back. A URL fragment
// such as #zoom=2&split=0.25&keys=ArrowRight,ArrowRight drives the first A/B view through its real
// zoom button, pointer and keyboard handlers so that test can check the divider moves; one such as
// #bless-tick=a,b&bless-reason=why ticks cases and types a reason (runBlessHook).
const char* const kReportJs = R"JS(
(function () {
  'use strict';
  var body = document.body;
  window.addEventListener('error', function (e) {
    body.setAttribute('data-js-error', String(e.message || e));
  });
  function setSplit(el, f) {
    f = Math.min(1, Math.max(0, f));
    el.taaPos = f;  // exact, so repeated key steps do not accumulate rounding
    el.setAttribute('data-pos', f.toFixed(4));
    el.querySelector('.ab-golden').style.clipPath =
        'inset(0 ' + ((1 - f) * 100).toFixed(2) + '% 0 0)';
    el.querySelector('.divider').style.left = (f * 100).toFixed(2) + '%';
    el.setAttribute('aria-valuenow', String(Math.round(f * 100)));
  }
  function splitAt(el, clientX) {
    var r = el.getBoundingClientRect();
    if (r.width > 0) setSplit(el, (clientX - r.left) / r.width);
  }
  function initSplit(el) {
    var dragging = false;
    el.addEventListener('pointerdown', function (e) {
      if (e.button > 0) return;
      dragging = true;
      try { el.setPointerCapture(e.pointerId); } catch (ignored) { /* synthetic events */ }
      splitAt(el, e.clientX);
      el.focus({preventScroll: true});
      e.preventDefault();
    });
    el.addEventListener('pointermove', function (e) { if (dragging) splitAt(el, e.clientX); });
    function stop() { dragging = false; }
    el.addEventListener('pointerup', stop);
    el.addEventListener('pointercancel', stop);
    el.addEventListener('keydown', function (e) {
      // One image pixel per key press (ten with Shift), so the divider can sit on any column.
      var w = el.querySelector('.ab-actual').naturalWidth || 100;
      var step = (e.shiftKey ? 10 : 1) / w;
      var f = el.taaPos;
      if (e.key === 'ArrowLeft') setSplit(el, f - step);
      else if (e.key === 'ArrowRight') setSplit(el, f + step);
      else if (e.key === 'Home') setSplit(el, 0);
      else if (e.key === 'End') setSplit(el, 1);
      else return;
      e.preventDefault();
    });
    setSplit(el, 0.5);
  }
  function setZoom(ab, z) {
    var img = ab.querySelector('.ab-actual');
    if (img.naturalWidth > 0) img.style.width = (img.naturalWidth * z) + 'px';
    ab.setAttribute('data-zoom', String(z));
    // Side labels would cover most of a tiny image; the toolbar names the sides anyway.
    ab.classList.toggle('small', img.naturalWidth * z < 240);
    ab.querySelectorAll('button.zoom').forEach(function (b) {
      b.setAttribute('aria-pressed', b.getAttribute('data-zoom') === String(z) ? 'true' : 'false');
    });
  }
  // Until the user picks one: the largest zoom whose image still fits, so small frames show
  // their pixels without a click.
  function autoZoom(ab) {
    var n = ab.querySelector('.ab-actual').naturalWidth;
    var room = Math.min(ab.clientWidth || 1024, 1024);
    var z = [8, 4, 2, 1].filter(function (k) { return n * k <= room; })[0] || 1;
    setZoom(ab, z);
  }
  function whenLoaded(img, f) {
    if (img.complete && img.naturalWidth > 0) f();
    else img.addEventListener('load', f);
  }
  document.querySelectorAll('.ab').forEach(function (ab) {
    initSplit(ab.querySelector('.split'));
    ab.querySelectorAll('button.zoom').forEach(function (b) {
      b.addEventListener('click', function () {
        setZoom(ab, Number(b.getAttribute('data-zoom')));
      });
    });
    whenLoaded(ab.querySelector('.ab-actual'), function () {
      if (ab.getAttribute('data-zoom') === 'auto') autoZoom(ab);
    });
  });
  // Golden, actual and diff share a third of the width each: small frames are magnified by a
  // whole factor (pixelated), large ones scaled down smoothly rather than by dropping pixels.
  document.querySelectorAll('.triptych img').forEach(function (img) {
    whenLoaded(img, function () {
      var room = (img.closest('.triptych').clientWidth - 20) / 3;
      var n = img.naturalWidth;
      if (n <= room) {
        img.style.width = (n * Math.min(8, Math.max(1, Math.floor(room / n)))) + 'px';
      } else {
        img.classList.add('fit');
      }
    });
  });
  // Crops arrive magnified already; small ones get another whole factor to about 256 px.
  document.querySelectorAll('.crops img').forEach(function (img) {
    whenLoaded(img, function () {
      var n = img.naturalWidth;
      img.style.width = (n * Math.min(4, Math.max(1, Math.floor(256 / n)))) + 'px';
    });
  });
  document.querySelectorAll('button.copy').forEach(function (b) {
    b.addEventListener('click', function () {
      var code = b.parentNode.querySelector('code');
      var text = code.textContent;
      function select() {
        var range = document.createRange();
        range.selectNodeContents(code);
        var s = window.getSelection();
        s.removeAllRanges();
        s.addRange(range);
      }
      if (navigator.clipboard && navigator.clipboard.writeText) {
        navigator.clipboard.writeText(text).then(function () { b.textContent = 'copied'; }, select);
      } else {
        select();
      }
    });
  });
  // `bless --from` for the ticked cases. Words a POSIX shell takes literally stay bare; others,
  // and the reason always, go in single quotes, each ' written as '\''.
  function shellQuote(s) { return "'" + s.replace(/'/g, "'\\''") + "'"; }
  function shellWord(s) { return /^[A-Za-z0-9_\/.,:=+@%-]+$/.test(s) ? s : shellQuote(s); }
  function blessPicks() {
    return Array.prototype.slice.call(document.querySelectorAll('input.bless-pick'));
  }
  function updateBless() {
    var picks = blessPicks();
    var ticked = picks.filter(function (p) { return p.checked; });
    var all = document.getElementById('bless-all');
    all.checked = ticked.length === picks.length;
    all.indeterminate = ticked.length > 0 && ticked.length < picks.length;
    var dir = document.getElementById('bless-dir').value.trim();
    var reason = document.getElementById('bless-reason').value.trim();
    var missing = [];
    if (!ticked.length) missing.push('tick at least one case');
    if (!reason) missing.push('type a reason');
    if (!dir) missing.push('give the run folder');
    var box = document.getElementById('bless-command');
    var hint = document.getElementById('bless-hint');
    box.hidden = missing.length > 0;
    hint.hidden = !box.hidden;
    if (box.hidden) {
      hint.textContent = 'No command yet: ' + missing.join(', ') + '.';
      return;
    }
    var words = ['taa-harness', 'bless', '--from', shellWord(dir)];
    ticked.forEach(function (p) { words.push(shellWord(p.getAttribute('data-file'))); });
    words.push('--reason', shellQuote(reason));
    box.querySelector('code').textContent = words.join(' ');
    box.querySelector('button.copy').textContent = 'copy';
  }
  // The folder this page was opened from: where the run wrote it, or where a CI artifact was
  // unpacked. A page from a web server has none to offer; the field says what to type.
  function pageFolder() {
    if (location.protocol !== 'file:') return '';
    try {
      var p = decodeURIComponent(location.pathname);
      return p.slice(0, p.lastIndexOf('/')) || '/';
    } catch (ignored) {
      return '';
    }
  }
  if (document.getElementById('bless-from')) {
    var dirField = document.getElementById('bless-dir');
    if (!dirField.value) dirField.value = pageFolder();
    blessPicks().forEach(function (p) { p.addEventListener('change', updateBless); });
    document.getElementById('bless-all').addEventListener('change', function (e) {
      blessPicks().forEach(function (p) { p.checked = e.target.checked; });
      updateBless();
    });
    ['bless-dir', 'bless-reason'].forEach(function (id) {
      document.getElementById(id).addEventListener('input', updateBless);
    });
    updateBless();
    // A reload may restore ticks and text after this script ran.
    window.addEventListener('pageshow', updateBless);
  }
  // #bless-tick=CASE,CASE&bless-reason=R&bless-dir=D[&bless-all=1] ticks, types the reason,
  // then the folder, and clicks select-all twice, through the real controls, recording on <body>
  // what the page shows after each step.
  function runBlessHook(params) {
    if (!params.has('bless-tick') || !document.getElementById('bless-from')) return;
    function shown() {
      var box = document.getElementById('bless-command');
      return box.hidden ? 'hint: ' + document.getElementById('bless-hint').textContent
                        : box.querySelector('code').textContent;
    }
    params.get('bless-tick').split(',').filter(Boolean).forEach(function (name) {
      blessPicks().forEach(function (p) { if (p.getAttribute('data-case') === name) p.click(); });
    });
    body.setAttribute('data-bless-before-reason', shown());
    function type(id) {
      if (!params.has(id)) return;
      var el = document.getElementById(id);
      el.value = params.get(id);
      el.dispatchEvent(new Event('input', {bubbles: true}));
    }
    type('bless-reason');
    body.setAttribute('data-bless-here', shown());
    type('bless-dir');
    body.setAttribute('data-bless-command', shown());
    if (!params.has('bless-all')) return;
    var all = document.getElementById('bless-all');
    all.click();
    body.setAttribute('data-bless-all', shown());
    all.click();
    body.setAttribute('data-bless-none', shown());
  }
  function runFragmentHook() {
    var params = new URLSearchParams(location.hash.replace(/^#/, ''));
    runBlessHook(params);
    var el = document.querySelector('.split');
    if (!params.has('split') || !el) return;
    var zoom = el.closest('.ab').querySelector(
        'button.zoom[data-zoom="' + params.get('zoom') + '"]');
    if (zoom) zoom.click();
    body.setAttribute('data-split-width', String(el.getBoundingClientRect().width));
    var r = el.getBoundingClientRect();
    var x = r.left + parseFloat(params.get('split')) * r.width;
    var opts = {clientX: x, clientY: r.top + 1, pointerId: 1, bubbles: true, button: 0,
                isPrimary: true, pointerType: 'mouse'};
    el.dispatchEvent(new PointerEvent('pointerdown', opts));
    el.dispatchEvent(new PointerEvent('pointerup', opts));
    body.setAttribute('data-split-after-pointer', el.getAttribute('data-pos'));
    (params.get('keys') || '').split(',').filter(Boolean).forEach(function (k) {
      el.dispatchEvent(new KeyboardEvent('keydown', {key: k, bubbles: true}));
    });
    body.setAttribute('data-split-after-keys', el.getAttribute('data-pos'));
  }
  window.addEventListener('load', function () {
    var imgs = Array.prototype.slice.call(document.images);
    var broken = imgs.filter(function (i) { return !(i.complete && i.naturalWidth > 0); });
    body.setAttribute('data-images-loaded', (imgs.length - broken.length) + '/' + imgs.length);
    body.setAttribute('data-images-broken',
                      broken.map(function (i) { return i.getAttribute('src'); }).join(' '));
    runFragmentHook();
    // A status badge is one line of its own text: a taller one (a wrapped label, a loose line
    // height) stretches every table row it sits in.
    var tall = Array.prototype.filter.call(document.querySelectorAll('.badge'), function (b) {
      return b.getBoundingClientRect().height > 1.75 * parseFloat(getComputedStyle(b).fontSize);
    });
    body.setAttribute('data-badges-tall', String(tall.length));
    var cases = document.querySelectorAll('section.case').length;
    var ok = cases === Number(body.getAttribute('data-case-count')) &&
             document.querySelector('header.run') !== null && !body.hasAttribute('data-js-error');
    body.setAttribute('data-render-ok', ok ? '1' : '0');
  });
})();
)JS";

}  // namespace taa::report::detail
