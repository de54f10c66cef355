// The turning-moment diagram's page: moves the cursor over the plots and writes the values
// at it. Everything shown is in the page's data, computed and formatted by the tool.
// On a mechanism's page (the data's "follow"), the cursor follows the mechanism's frame
// (the "pm-frame" event of page.js) and the values go to the data's own table.
(function () {
  "use strict";
  const D = JSON.parse(document.getElementById("cycle").textContent);
  const slider = document.getElementById("angle");
  const now = document.getElementById("angle-now");
  const body = document.querySelector("#" + (D.table || "values") + " tbody");
  const cells = D.rows.map(function (row) {
    const tr = document.createElement("tr");
    const th = document.createElement("th");
    const td = document.createElement("td");
    th.textContent = row[0];
    tr.appendChild(th);
    tr.appendChild(td);
    body.appendChild(tr);
    return td;
  });
  const plots = D.cursor.map(function (c) {
    return {
      line: document.getElementById(c[0] + "-cursor"),
      dot: document.getElementById(c[0] + "-dot"),
      xs: c[1],
      ys: c[2],
    };
  });
  function show(k) {
    plots.forEach(function (p) {
      p.line.setAttribute("x1", p.xs[k]);
      p.line.setAttribute("x2", p.xs[k]);
      p.dot.setAttribute("cx", p.xs[k]);
      p.dot.setAttribute("cy", p.ys[k]);
    });
    D.rows.forEach(function (row, i) {
      cells[i].textContent = row[1][k];
    });
    if (!D.follow) now.textContent = D.rows[0][1][k];
  }
  if (D.follow) {
    document.addEventListener("pm-frame", function (ev) {
      show(ev.detail);
    });
    show(Number(slider.value));
    return;
  }
  slider.addEventListener("input", function () {
    show(Number(slider.value));
  });
  const play = document.getElementById("play");
  let timer = null;
  play.addEventListener("click", function () {
    if (timer !== null) {
      clearInterval(timer);
      timer = null;
      play.textContent = "▶ play";
      return;
    }
    play.textContent = "❚❚ pause";
    timer = setInterval(function () {
      slider.value = (Number(slider.value) + 1) % D.n;
      show(Number(slider.value));
    }, D.n > 40 ? 60 : 500);
  });
  show(Number(slider.value));
})();

// printed: the folded parts (the step table, the problem) opened for the paper, and
// folded again after (one handler, whichever of the page's scripts comes first)
if (!window.pmPrint) {
  window.pmPrint = [];
  window.addEventListener("beforeprint", function () {
    window.pmPrint = Array.prototype.filter.call(document.querySelectorAll("details"), function (d) { return !d.open; });
    window.pmPrint.forEach(function (d) { d.open = true; });
  });
  window.addEventListener("afterprint", function () {
    window.pmPrint.forEach(function (d) { d.open = false; });
    window.pmPrint = [];
  });
}
