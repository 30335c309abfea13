/* handmotion's pkgdown.js: pkgdown 2.0's BS5 script (MIT, RStudio) adapted
 * so that the site works offline and from file://:
 * - the page contents ("On this page") are built here, not by bootstrap-toc
 *   from a CDN;
 * - headroom is called directly (its jQuery plugin is gone from headroom 0.11);
 * - the search index is a script (search-index.js, written by tools/site.sh
 *   from pkgdown's search.json) loaded on first use: a browser refuses
 *   fetch() of a file:// URL, but loads a script from one;
 * - search results link relative to the site's root, wherever it lies;
 * - the copy button draws its icon inline (no icon font). */
(function($) {
  $(function() {

    var navbar = document.querySelector('nav.navbar');
    if (navbar && window.Headroom) new Headroom(navbar).init();

    /* Page contents ----------------------------*/
    // One link per h2 and h3 of the page's main text (not those marked
    // data-toc-skip), nested as the headings are. pkgdown puts the anchor id
    // on the heading's section; a heading without one gets an id from its text.
    function buildToc($nav, headings) {
      var used = {};
      var root = $('<ul class="nav nav-pills flex-column"></ul>');
      var current = null;
      headings.each(function() {
        var h = this;
        if (h.hasAttribute('data-toc-skip')) return;
        var id = h.id || (h.parentElement && /\bsection\b/.test(h.parentElement.className) ? h.parentElement.id : '');
        if (!id) {
          id = ($(h).text().trim().toLowerCase().replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '') || 'section');
          while (used[id] || document.getElementById(id)) id += '-1';
          h.id = id;
        }
        used[id] = true;
        var text = $(h).clone().find('.anchor').remove().end().text().trim();
        var li = $('<li></li>').append($('<a class="nav-link"></a>').attr('href', '#' + id).text(text));
        if (h.tagName === 'H2' || !current) {
          root.append(li);
          current = li;
        } else {
          var sub = current.children('ul');
          if (!sub.length) sub = $('<ul class="nav nav-pills flex-column"></ul>').appendTo(current);
          sub.append(li);
        }
      });
      // after the nav's own "On this page" heading
      $nav.children('ul.nav').remove();
      $nav.append(root);
      return root.find('a').length;
    }
    var $toc = $('#toc');
    if ($toc.length) {
      var n = buildToc($toc, $('main h2, main h3'));
      if (!n) $toc.hide();  // a page without sections: no empty heading
      $('body').scrollspy({
        target: '#toc',
        offset: $("nav.navbar").outerHeight() + 1
      });
    }

    // Activate popovers
    $('[data-bs-toggle="popover"]').popover({
      container: 'body',
      html: true,
      trigger: 'focus',
      placement: "top",
      sanitize: false,
    });

    $('[data-bs-toggle="tooltip"]').tooltip();

  /* Clipboard --------------------------*/

  function changeTooltipMessage(element, msg) {
    var tooltipOriginalTitle=element.getAttribute('data-original-title');
    element.setAttribute('data-original-title', msg);
    $(element).tooltip('show');
    element.setAttribute('data-original-title', tooltipOriginalTitle);
  }

  if(window.ClipboardJS && ClipboardJS.isSupported()) {
    $(document).ready(function() {
      var copyIcon = "<svg width='14' height='14' viewBox='0 0 16 16' aria-hidden='true'><path fill='currentColor' d='M4 2h7v1H4v9H3V2.5A.5.5 0 0 1 3.5 2zM5.5 4h7a.5.5 0 0 1 .5.5v9a.5.5 0 0 1-.5.5h-7a.5.5 0 0 1-.5-.5v-9a.5.5 0 0 1 .5-.5zM6 5v8h6V5z'/></svg>";
      var copyButton = "<button type='button' class='btn btn-primary btn-copy-ex' title='Copy to clipboard' aria-label='Copy to clipboard' data-toggle='tooltip' data-placement='left' data-trigger='hover' data-clipboard-copy>" + copyIcon + "</button>";

      $("div.sourceCode").addClass("hasCopyButton");

      // Insert copy buttons:
      $(copyButton).prependTo(".hasCopyButton");

      // Initialize tooltips:
      $('.btn-copy-ex').tooltip({container: 'body'});

      // Initialize clipboard:
      var clipboard = new ClipboardJS('[data-clipboard-copy]', {
        text: function(trigger) {
          return trigger.parentNode.textContent.replace(/\n#>[^\n]*/g, "");
        }
      });

      clipboard.on('success', function(e) {
        changeTooltipMessage(e.trigger, 'Copied!');
        e.clearSelection();
      });

      clipboard.on('error', function(e) {
        changeTooltipMessage(e.trigger,'Press Ctrl+C or Command+C to copy');
      });

    });
  }

    /* Search marking --------------------------*/
    var url = new URL(window.location.href);
    var toMark = url.searchParams.get("q");
    if (toMark && window.Mark) {
      var mark = new Mark("main#main");
      mark.mark(toMark, {
        accuracy: {
          value: "complementary",
          limiters: [",", ".", ":", "/"],
        }
      });
    }

  /* Search --------------------------*/
  /* Adapted from bookdown's bs4_book.js (MIT). */
  var $input = $("#search-input");
  if (!$input.length) return;
  // the site's root as this page sees it: the index lies there
  var siteRoot = ($input.data("search-index") || "search.json").replace(/search\.json$/, "");
  var fuse;
  var loading;
  // The index as a script (window.pkgdownSearchIndex): works from file://
  // and from a web server alike.
  function loadIndex() {
    if (fuse) return Promise.resolve(fuse);
    if (!loading) {
      $input.addClass("loading");
      loading = new Promise(function(resolve) {
        var done = function() {
          var data = window.pkgdownSearchIndex || [];
          fuse = new Fuse(data, {
            // a page's or section's title counts more than its text
            keys: [{name: "title", weight: 3}, {name: "what", weight: 2}, {name: "text", weight: 1},
                   {name: "code", weight: 1}],
            ignoreLocation: true,
            threshold: 0.1,
            includeMatches: true,
            includeScore: true,
          });
          $input.removeClass("loading");
          resolve(fuse);
        };
        if (window.pkgdownSearchIndex) return done();
        var s = document.createElement("script");
        s.src = siteRoot + "search-index.js";
        s.onload = done;
        s.onerror = function() { console.warn("search: no search-index.js at " + s.src); done(); };
        document.head.appendChild(s);
      });
    }
    return loading;
  }
  $input.on("focus", loadIndex);

  // an index path ("/articles/x.html", from the site's root) as an absolute
  // URL: resolved against this page, not against whichever script happens
  // to run the selection
  function fromRoot(path) {
    return new URL(/^[a-z]+:/i.test(path) ? path : siteRoot + path.replace(/^\//, ""), window.location.href).href;
  }

  var options = {
    autoselect: true,
    debug: true,
    hint: false,
    minLength: 2,
  };
  var q;
  function searchFuse(query, callback) {
    loadIndex().then(function(f) {
      q = query;
      // reference pages first (a reader searching a function's name wants
      // its help page), then the articles and the home page, the changelog
      // last; by Fuse's score within each
      var tier = function(path) {
        var p = String(path || "").replace(/^[a-z]+:\/\/[^/]*/i, "").replace(/^\//, "");
        return /^reference\//.test(p) ? 0 : (/^news\//.test(p) ? 2 : 1);
      };
      var items = f.search(query, { limit: 40 })
        .filter(function(x) { return x.score <= 0.75; })
        .sort(function(a, b) { return (tier(a.item.path) - tier(b.item.path)) || (a.score - b.score); })
        .slice(0, 20)
        .map(function(x) { return x.item; });
      if (items.length === 0) {
        items = [{dir: "", previous_headings: "", title: "No results found.", what: "No results found.", path: ""}];
      }
      callback(items);
    });
  }
  $input.autocomplete(options, [
    {
      name: "content",
      source: searchFuse,
      templates: {
        suggestion: function(s) {
          var esc = function(x) { return $("<span>").text(x || "").html(); };
          if (s.title == s.what) {
            return esc(s.dir) + " >\t<div class=\"search-details\"> " + esc(s.title) + "</div>";
          } else if (s.previous_headings == "") {
            return esc(s.dir) + " >\t<div class=\"search-details\"> " + esc(s.title) + "</div> > " + esc(s.what);
          } else {
            return esc(s.dir) + " >\t<div class=\"search-details\"> " + esc(s.title) + "</div> > " +
              esc(s.previous_headings) + " > " + esc(s.what);
          }
        },
      },
    },
  ]).on('autocomplete:selected', function(event, s) {
    if (!s.path) return;
    window.location.href = fromRoot(s.path) + "?q=" + encodeURIComponent(q) + "#" + s.id;
  });
  });
})(window.jQuery || window.$)
