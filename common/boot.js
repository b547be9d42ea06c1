// A classic (non-module) script every page loads first. Module scripts and fetch() of shader files
// do not work from file://, so there the page says how to open it instead of staying blank.
(function () {
  if (location.protocol !== 'file:') return;
  document.addEventListener('DOMContentLoaded', function () {
    var area = document.getElementById('messages') || document.body;
    var item = document.createElement('div');
    item.className = 'error';
    item.textContent = 'This page was opened from a file (file://), where browsers block its module ' +
      'script and shader files. Serve the site instead: in the project folder run "npm start" and ' +
      'open the address it prints (http://127.0.0.1:8080/).';
    area.append(item);
  });
})();
