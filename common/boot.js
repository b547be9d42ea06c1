// A classic (non-module) script every exercise loads first. Once the page is parsed it runs the
// step's WebGL script, or its WebGPU script when the address asks for ?api=webgpu:
//   <script src="../common/boot.js" data-webgl="main.js" data-webgpu="webgpu.js"></script>
// Module scripts and fetch() of shader files do not work from file://, so there the page says how
// to open it instead of staying blank.
(function () {
  var me = document.currentScript;
  var api = new URLSearchParams(location.search).get('api');
  var src = me && (api === 'webgpu' ? me.dataset.webgpu : me.dataset.webgl);
  document.addEventListener('DOMContentLoaded', function () {
    if (location.protocol !== 'file:') {
      if (!src) return;
      var script = document.createElement('script');
      script.type = 'module';
      script.src = src;
      document.head.append(script);
      return;
    }
    var area = document.getElementById('messages') || document.body;
    var item = document.createElement('div');
    item.className = 'error';
    item.textContent = 'This page was opened from a file (file://), where browsers block its module ' +
      'script and shader files. Serve the site instead: in the project folder run "npm start" and ' +
      'open the address it prints (http://127.0.0.1:8080/).';
    area.append(item);
  });
})();
