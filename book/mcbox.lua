-- book/mcbox.lua - the pandoc filter that ties the book to the code.
--
-- Five kinds of element in a chapter are resolved from the real tree when
-- the book is built, so that nothing in the text can drift from the code:
--
--   ```{.listing file=mc/pi.c name=pi_plain}
--   ```                     a region of a source file, cut by its markers
--                           BEGIN SNIPPET name / END SNIPPET name (any
--                           comment syntax); shown with its path, its first
--                           line number and a link to the whole file.
--   ```{.run id=pi}
--   pi --samples 1e6 --seed 1 --csv
--   ```                     a command run from the build's bin/ (tests/,
--                           exercises/),
--                           shown with exactly what it printed; .hide keeps
--                           it out of the page (a run that only feeds
--                           numbers), stderr=true shows stderr too,
--                           status=N expects that exit status (default 0);
--                           MC_BUILD and MC_SOURCE name the build and the
--                           source tree.
--   [?]{.num run=pi col=estimate where=method=plain fmt=%.5f}
--                           a number in a sentence: one cell of a run's CSV
--                           output (row=K or where=COLUMN=VALUE picks the
--                           row, default the first); over-col= (with
--                           over-run= and over-where=, defaulting to the
--                           same run and row) divides it by another cell.
--   ![caption](plot:pi_convergence)
--                           a figure of `make plots`, with the command that
--                           regenerates it; ![caption](run:file.png) is an
--                           image a run of this chapter wrote.
--   [@veach1997]            a citation: a link to the entry of that key on the
--                           references page (book/references.md); see
--                           "Citations" below.
--   ::: {.tests run=ID}     a box of tests: a pipe table whose rows name a
--   | test | ... | verdict |  test in backticks; each verdict is filled
--   :::                     from the cmocka output of the run ID.
--
-- Every error stops the build with "file:line: message" on stderr and exit
-- status 1. The environment says where things are: BOOK_BUILD (the build
-- directory with bin/, tests/, plots/), BOOK_OUT (the book's output
-- directory), BOOK_SRC (the root listings are cut from, default "."),
-- BOOK_STATE (a directory for run outputs, shared by the HTML and EPUB
-- passes of one build, and the record of used regions).

local build = os.getenv("BOOK_BUILD") or "build"
local out = os.getenv("BOOK_OUT") or (build .. "/book")
local src_root = os.getenv("BOOK_SRC") or "."
local state = os.getenv("BOOK_STATE") or (build .. "/book-state")
local rundir = os.getenv("BOOK_RUNS") or (state .. "/runs-cwd")
-- The EPUB is built from per-chapter Markdown that this filter wrote; the
-- pages of whole source files exist only beside the HTML.
local no_links = FORMAT:match("epub") ~= nil or FORMAT:match("markdown") ~= nil

local chapter = (PANDOC_STATE.input_files or {})[1] or "<stdin>"

-- Errors ------------------------------------------------------------------

local function die(where, msg)
  io.stderr:write(where .. ": " .. msg .. "\n")
  os.exit(1)
end

-- The line of the chapter that mentions `needle` (pandoc's Markdown reader
-- keeps no source positions), so that errors point at the element.
local chapter_lines
local function chapter_where(needle, nth)
  if not chapter_lines then
    chapter_lines = {}
    local f = io.open(chapter, "r")
    if f then
      for l in f:lines() do chapter_lines[#chapter_lines + 1] = l end
      f:close()
    end
  end
  local seen = 0
  for i, l in ipairs(chapter_lines) do
    if needle and l:find(needle, 1, true) then
      seen = seen + 1
      if seen >= (nth or 1) then return chapter .. ":" .. i end
    end
  end
  return chapter .. ":1"
end

local function shell_quote(s)
  return "'" .. s:gsub("'", "'\\''") .. "'"
end

local function read_file(path)
  local f = io.open(path, "rb")
  if not f then return nil end
  local s = f:read("a")
  f:close()
  return s
end

local function write_file(path, s)
  local f = assert(io.open(path, "wb"))
  f:write(s)
  f:close()
end

-- Records of what the build used; only the HTML pass writes them, so that
-- each listing, run, number and figure is counted once.
local function append_line(path, s)
  if no_links then return end
  local f = io.open(path, "a")
  if f then
    f:write(s, "\n")
    f:close()
  end
end

-- Listings ----------------------------------------------------------------

local BEGIN = "BEGIN SNIPPET%s+([%w_%-%.]+)"
local END = "END SNIPPET%s+([%w_%-%.]+)"

-- Parses every marked region of one file: name -> {first, last, lines}
-- where first..last are the region's line numbers (markers excluded).
local regions_cache = {}
local function regions_of(path)
  if regions_cache[path] then return regions_cache[path] end
  local f = io.open(src_root .. "/" .. path, "r")
  if not f then return nil end
  local lines = {}
  for l in f:lines() do lines[#lines + 1] = l end
  f:close()
  local regions, open = {}, nil
  for i, l in ipairs(lines) do
    local b, e = l:match(BEGIN), l:match(END)
    if b then
      if open then
        die(path .. ":" .. i, "region '" .. b .. "' begins inside region '" .. open.name ..
          "' (opened at line " .. open.at .. "); regions may not nest")
      end
      if regions[b] then
        die(path .. ":" .. i, "region '" .. b .. "' is marked twice (first at line " ..
          (regions[b].first - 1) .. ")")
      end
      open = { name = b, at = i }
    elseif e then
      if not open then
        die(path .. ":" .. i, "END SNIPPET " .. e .. " without a BEGIN")
      end
      if e ~= open.name then
        die(path .. ":" .. i, "END SNIPPET " .. e .. " closes region '" .. open.name ..
          "' (opened at line " .. open.at .. ")")
      end
      local body, blank = {}, true
      for k = open.at + 1, i - 1 do
        body[#body + 1] = lines[k]
        if lines[k]:match("%S") then blank = false end
      end
      if blank then
        die(path .. ":" .. open.at, "region '" .. e .. "' is empty")
      end
      regions[e] = { first = open.at + 1, last = i - 1, lines = body }
      open = nil
    end
  end
  if open then
    die(path .. ":" .. open.at, "region '" .. open.name .. "' is never closed")
  end
  regions_cache[path] = regions
  return regions
end

-- Removes the indentation every non-blank line of the region shares.
local function dedent(lines)
  local common
  for _, l in ipairs(lines) do
    if l:match("%S") then
      local ind = #l:match("^[ ]*")
      if not common or ind < common then common = ind end
    end
  end
  local outl = {}
  for i, l in ipairs(lines) do outl[i] = l:sub((common or 0) + 1) end
  return table.concat(outl, "\n")
end

local language_of = {
  c = "c", h = "c", sh = "bash", gp = "gnuplot", awk = "awk", lua = "lua", inc = "makefile",
}

local function source_page(path)
  return "src/" .. path .. ".html"
end

local function listing(el)
  local path, name = el.attributes.file, el.attributes.name
  local where = chapter_where("name=" .. (name or ""))
  if not path or not name then die(where, "a listing needs file= and name=") end
  local regions = regions_of(path)
  if not regions then die(where, "listing file '" .. path .. "' does not exist") end
  local r = regions[name]
  if not r then die(where, "no region '" .. name .. "' in " .. path) end
  append_line(state .. "/used-regions", path .. " " .. name)
  append_line(state .. "/used-files", path)
  local ext = path:match("%.([%w]+)$") or ""
  local classes = { language_of[ext] or ext, "numberLines" }
  local code = pandoc.CodeBlock(dedent(r.lines),
    pandoc.Attr("", classes, { { "startFrom", tostring(r.first) } }))
  local label = path .. ", line " .. r.first
  local head
  if no_links then
    head = pandoc.Plain({ pandoc.Code(path), pandoc.Str(", line " .. r.first) })
  else
    head = pandoc.Plain({ pandoc.Link({ pandoc.Code(path), pandoc.Str(", line " .. r.first) },
      source_page(path) .. "#L-" .. r.first, "the whole of " .. label) })
  end
  return pandoc.Div({ pandoc.Div({ head }, pandoc.Attr("", { "listing-file" })), code },
    pandoc.Attr("", { "listing" }, { { "data-region", name } }))
end

-- Runs --------------------------------------------------------------------

local runs = {}        -- id -> { out = text, csv = parsed or nil }
local run_count = 0

local function parse_csv(text)
  local rows = {}
  for line in text:gmatch("[^\n]+") do
    local cells = {}
    for cell in (line .. ","):gmatch("([^,]*),") do cells[#cells + 1] = cell end
    rows[#rows + 1] = cells
  end
  if #rows < 2 then return nil end
  return rows
end

local function key_of(s)
  -- A file name for a command's cached output: its bytes as hex would be
  -- long, so a simple 64-bit-ish polynomial hash with the length.
  local h1, h2 = 5381, 52711
  for i = 1, #s do
    local c = s:byte(i)
    h1 = (h1 * 33 + c) % 4294967296
    h2 = (h2 * 31 + c) % 4294967296
  end
  return string.format("%08x%08x-%d", h1, h2, #s)
end

local function run(el)
  local cmd = el.text:gsub("%s+$", "")
  local id = el.identifier ~= "" and el.identifier or el.attributes.id
  local where = id and (chapter_where("#" .. id) ~= chapter .. ":1" and chapter_where("#" .. id)
    or chapter_where("id=" .. id)) or chapter_where(cmd:match("[^\n]*"))
  if cmd == "" then die(where, "a run block with no command") end
  local want = tonumber(el.attributes.status or "0")
  local with_err = el.attributes.stderr == "true"
  local key = key_of(cmd .. "\0" .. tostring(with_err))
  local cached = state .. "/runs/" .. key
  local outtext = read_file(cached .. ".out")
  if not outtext then
    -- Two chapters built at once may run the same command: the lock makes
    -- the second wait for the first and take its output (the command runs
    -- only when no output is there once the lock is held).
    local q = function(ext) return shell_quote(cached .. ext) end
    local script = "exec 9>" .. q(".lock") .. " && flock 9 && [ -e " .. q(".out") .. " ] || { " ..
      "t0=$(date +%s%N); cd " .. shell_quote(rundir) .. " && PATH=" ..
      shell_quote(build .. "/bin:" .. build .. "/tests:" .. build .. "/exercises") .. ":\"$PATH\" " ..
      "MC_BUILD=" .. shell_quote(build) .. " MC_SOURCE=" .. shell_quote(src_root) .. " bash -o pipefail -c " .. shell_quote(cmd) ..
      " >" .. q(".tmp") .. (with_err and " 2>&1" or " 2>" .. q(".err")) ..
      "; echo $? >" .. q(".rc") ..
      "; echo $((($(date +%s%N) - t0) / 1000000)) >" .. q(".ms") ..
      "; mv " .. q(".tmp") .. " " .. q(".out") .. "; }"
    os.execute("mkdir -p " .. shell_quote(rundir) .. " " .. shell_quote(state .. "/runs"))
    os.execute("bash -c " .. shell_quote(script))
    local rc = tonumber((read_file(cached .. ".rc") or "1"):match("%d+"))
    outtext = read_file(cached .. ".out") or ""
    if rc ~= want then
      os.remove(cached .. ".out")
      local err = read_file(cached .. ".err") or outtext
      die(where, "command `" .. cmd .. "` exited with status " .. rc .. " (expected " .. want ..
        ")" .. (err ~= "" and (": " .. err:gsub("\n+$", "")) or ""))
    end
    append_line(state .. "/run-times", (read_file(cached .. ".ms") or "?\n"):gsub("\n", "") ..
      " ms " .. cmd:gsub("\n", " "))
  end
  run_count = run_count + 1
  if id then
    if runs[id] then
      local second = chapter_where("#" .. id, 2)
      die(second ~= chapter .. ":1" and second or where, "two runs are named '" .. id .. "'")
    end
    runs[id] = { out = outtext, csv = parse_csv(outtext), cmd = cmd }
  end
  append_line(state .. "/run-count", chapter)
  if el.classes:includes("hide") then return {} end
  local shown = "$ " .. cmd:gsub("\n", "\n  ") .. "\n" .. outtext:gsub("\n$", "")
  return pandoc.Div({ pandoc.CodeBlock(shown, pandoc.Attr("", { "console" })) },
    pandoc.Attr("", { "run" }))
end

-- Numbers -----------------------------------------------------------------

local function cell(where, run_id, col, row, cond)
  local r = runs[run_id]
  if not r then die(where, "no run named '" .. tostring(run_id) .. "' before this number") end
  if not r.csv then die(where, "run '" .. run_id .. "' printed no CSV table") end
  local header = r.csv[1]
  local ci
  for i, h in ipairs(header) do if h == col then ci = i end end
  if not ci then
    die(where, "run '" .. run_id .. "' has no column '" .. tostring(col) .. "' (it has " ..
      table.concat(header, ", ") .. ")")
  end
  local pick
  if cond then
    local ccol, cval = cond:match("^([^=]+)=(.*)$")
    if not ccol then die(where, "where= takes COLUMN=VALUE, not '" .. cond .. "'") end
    local cc
    for i, h in ipairs(header) do if h == ccol then cc = i end end
    if not cc then die(where, "run '" .. run_id .. "' has no column '" .. ccol .. "'") end
    for k = 2, #r.csv do
      if r.csv[k][cc] == cval then
        if pick then die(where, "run '" .. run_id .. "' has several rows with " .. cond) end
        pick = r.csv[k]
      end
    end
    if not pick then die(where, "run '" .. run_id .. "' has no row with " .. cond) end
  else
    pick = r.csv[1 + (tonumber(row or "1") or 1)]
    if not pick then die(where, "run '" .. run_id .. "' has no row " .. tostring(row)) end
  end
  local v = pick[ci]
  if v == nil or v == "" then
    die(where, "run '" .. run_id .. "', column '" .. col .. "' is empty in that row")
  end
  return v
end

local function number(el)
  local a = el.attributes
  local where = chapter_where("run=" .. (a.run or "") .. " col=" .. (a.col or ""))
  if not a.run or not a.col then die(where, "a number needs run= and col=") end
  local v = cell(where, a.run, a.col, a.row, a.where)
  local fmt = a.fmt
  local over = a["over-col"]
  if over then
    local ov = cell(where, a["over-run"] or a.run, over, a["over-row"] or a.row,
      a["over-where"] or a.where)
    local x, y = tonumber(v), tonumber(ov)
    if not x or not y then die(where, "a ratio of '" .. v .. "' and '" .. ov .. "'") end
    v = x / y
  end
  if a.abs == "true" then
    if not tonumber(v) then die(where, "abs of '" .. v .. "'") end
    v = math.abs(tonumber(v))
  end
  local text
  if fmt then
    local x = tonumber(v)
    if not x then die(where, "format " .. fmt .. " of the text '" .. tostring(v) .. "'") end
    if fmt:match("d$") then x = math.floor(x + 0.5) end
    local ok, s = pcall(string.format, fmt, x)
    if not ok then die(where, "bad format " .. fmt) end
    text = s
  else
    text = tostring(v)
  end
  append_line(state .. "/number-count", chapter)
  return pandoc.Span({ pandoc.Str(text) }, pandoc.Attr("", { "num" },
    { { "title", "from the run '" .. a.run .. "', column " .. a.col } }))
end

-- Figures -----------------------------------------------------------------

local function copy(from, to)
  local data = read_file(from)
  if not data then return false end
  os.execute("mkdir -p " .. shell_quote(to:match("^(.*)/[^/]*$")))
  write_file(to, data)
  return true
end

local function image(el)
  local kind, name = el.src:match("^(%a+):(.+)$")
  if kind == "plot" then
    local where = chapter_where("plot:" .. name)
    local from = build .. "/plots/" .. name .. ".png"
    if not copy(from, out .. "/figures/" .. name .. ".png") then
      die(where, "no figure " .. from .. " (make plots writes it)")
    end
    el.src = "figures/" .. name .. ".png"
    el.attributes["data-regenerate"] = "make plots; plots/" .. name .. ".gp"
    append_line(state .. "/figures", "plot " .. name)
    return el
  elseif kind == "run" then
    local where = chapter_where("run:" .. name)
    local from = rundir .. "/" .. name
    local base = name:gsub("/", "_")
    if not copy(from, out .. "/figures/run-" .. base) then
      die(where, "no image " .. name .. " written by a run of this chapter")
    end
    el.src = "figures/run-" .. base
    append_line(state .. "/figures", "run " .. name)
    return el
  end
  return nil
end

-- A figure of `make plots` gets the command that regenerates it under its
-- caption.
local function para(el)
  if #el.content == 1 and el.content[1].t == "Image" then
    local img = el.content[1]
    local regen = img.attributes["data-regenerate"]
    if regen then
      img.attributes["data-regenerate"] = nil
      local stem = img.src:match("figures/(.+)%.png$")
      return pandoc.Div({ el, pandoc.Para({ pandoc.Str("Regenerate: "), pandoc.Code("make plots"),
        pandoc.Str(" (script "), pandoc.Code("plots/" .. stem .. ".gp"), pandoc.Str(", data "),
        pandoc.Code("plots/data_" .. stem .. ".sh"), pandoc.Str(")") }) },
        pandoc.Attr("", { "figure-block" }))
    end
  end
  return nil
end

-- Links ------------------------------------------------------------------
-- A link to #id that names an anchor of another chapter becomes
-- page.html#id on the HTML pages (one page per chapter); the EPUB, one
-- document, resolves #id itself. BOOK_STATE/anchors lists "id page" pairs.
-- A link whose text is a chapter's number ("chapter 6", "Chapters 8", or
-- the bare "6" of "chapters [3](#ch-sphere) and [4](#ch-scattering)")
-- must point into the page of that number (06-tests.html): a renumbered
-- chapter or a slip of the finger stops the build, in every format.

local anchors
local function link(el)
  if not el.target:match("^#") then return nil end
  if not anchors then
    anchors = {}
    local f = io.open(state .. "/anchors", "r")
    if f then
      for l in f:lines() do
        local id, page = l:match("^(%S+) (%S+)$")
        if id then anchors[id] = page end
      end
      f:close()
    end
  end
  local page = anchors[el.target:sub(2)]
  local text = pandoc.utils.stringify(el.content)
  local said = text:match("^[Cc]hapters? (%d+)$") or text:match("^(%d+)$")
  if said and page then
    local is = page:match("^(%d+)%-")
    if is and tonumber(is) ~= tonumber(said) then
      local where = chapter_where("[" .. text .. "](" .. el.target .. ")")
      if where == chapter .. ":1" then where = chapter_where("](" .. el.target .. ")") end
      die(where,
          "link '" .. text .. "' points at " .. el.target .. ", which is in chapter " ..
          tonumber(is) .. " (" .. page .. ")")
    end
  end
  if no_links then return nil end
  local here = chapter:match("([^/]+)%.md$")
  if page and page ~= here .. ".html" then el.target = page .. el.target end
  return el
end

-- Citations ---------------------------------------------------------------
-- [@key] in a chapter (pandoc's Cite; [@key, section 9.2] and [@a; @b]
-- too) becomes a link to the entry of the references page, book/
-- references.md (BOOK_REFS), where each entry is a Div
--   ::: {#ref-key .reference label="Veach 1997"}
-- whose label is the link's text. A key with no entry stops the build; the
-- HTML pass records every key in BOOK_STATE/used-cites, for the check of
-- the whole tree (check_citations) that also reads the code's comments.

local refs_page = "references"
local refs_path = os.getenv("BOOK_REFS") or (src_root .. "/book/" .. refs_page .. ".md")
local refs_name = os.getenv("BOOK_REFS") or ("book/" .. refs_page .. ".md")

local refs
local function references() -- key -> { line, label }
  if refs then return refs end
  refs = {}
  local f = io.open(refs_path, "r")
  if f then
    local i = 0
    for l in f:lines() do
      i = i + 1
      local key, rest = l:match("^:::+%s*{#ref%-([%w_%-]+)(.*)$")
      if key then
        if refs[key] then
          die(refs_name .. ":" .. i, "entry '" .. key .. "' is there twice (first at line " ..
            refs[key].line .. ")")
        end
        refs[key] = { line = i, label = rest:match('label="([^"]*)"') or key }
      end
    end
    f:close()
  end
  return refs
end

local function words(s) -- "Veach 1997" as inlines
  local inl = {}
  for w in s:gmatch("%S+") do
    if #inl > 0 then inl[#inl + 1] = pandoc.Space() end
    inl[#inl + 1] = pandoc.Str(w)
  end
  return inl
end

local function cite(el)
  local here = chapter:match("([^/]+)%.md$")
  local inl = {}
  local function add(xs) for _, x in ipairs(xs) do inl[#inl + 1] = x end end
  local in_text = #el.citations == 1 and el.citations[1].mode == "AuthorInText"
  if not in_text then inl[1] = pandoc.Str("[") end
  for i, c in ipairs(el.citations) do
    local e = references()[c.id]
    if not e then
      die(chapter_where("@" .. c.id), "citation [@" .. c.id .. "] has no entry in " .. refs_name)
    end
    append_line(state .. "/used-cites", c.id)
    local target = "#ref-" .. c.id
    if not no_links and here ~= refs_page then target = refs_page .. ".html" .. target end
    if i > 1 then add({ pandoc.Str(";"), pandoc.Space() }) end
    if #c.prefix > 0 then add(c.prefix); add({ pandoc.Space() }) end
    add({ pandoc.Link(words(e.label), target, "references: " .. e.label) })
    add(c.suffix)
  end
  if not in_text then inl[#inl + 1] = pandoc.Str("]") end
  return pandoc.Span(inl, pandoc.Attr("", { "citation" }))
end

-- An entry of the references page starts with its label, "[Veach 1997]", in bold.
local function reference_entry(el)
  if not el.classes:includes("reference") or not el.identifier:match("^ref%-") then return nil end
  local label = el.attributes.label or el.identifier:sub(5)
  el.attributes.label = nil
  local first = el.content[1]
  if first and (first.t == "Para" or first.t == "Plain") then
    first.content:insert(1, pandoc.Space())
    first.content:insert(1, pandoc.Strong(words("[" .. label .. "]")))
  end
  return el
end

-- HTML only ---------------------------------------------------------------
-- A block of class html-only (a link to the warp lab, a live widget) is
-- left out of the EPUB, whose readers run no scripts and have no lab page.

local function html_only(el)
  if no_links and el.classes:includes("html-only") then return {} end
  return nil
end

-- The tests box ----------------------------------------------------------
-- ::: {.tests run=ID} around a pipe table whose first column is a test
-- name in backticks and whose last column, "verdict", is left empty: each
-- name is looked up in the output of the run ID (cmocka prints
-- "[       OK ] name" or "[  FAILED  ] name"), and the verdict is filled
-- in. A name the run never printed, or one that failed, stops the build.
-- A name ending in * stands for every test whose name starts with the rest.

-- The line of the row naming `name`: the first one after the box opens.
local function row_where(run_id, name)
  chapter_where(nil)
  local open
  for i, l in ipairs(chapter_lines) do
    if not open and l:find("run=" .. run_id, 1, true) and l:find(".tests", 1, true) then open = i end
    if open and l:find("`" .. name .. "`", 1, true) then return chapter .. ":" .. i end
  end
  return open and (chapter .. ":" .. open) or chapter_where("run=" .. run_id)
end

local function tests_box(el)
  local run_id = el.attributes.run
  local where = chapter_where(".tests" .. (run_id and (" run=" .. run_id) or ""))
  if not run_id then die(where, "a tests box needs run=") end
  local r = runs[run_id]
  if not r then die(where, "no run named '" .. run_id .. "' in this chapter") end
  local ok, failed = {}, {}
  for line in r.out:gmatch("[^\n]+") do
    local n = line:match("^%[       OK %] (.-)%s*$")
    if n then ok[n] = true end
    n = line:match("^%[  FAILED  %] (.-)%s*$")
    if n then failed[n] = true end
  end
  local tables = 0
  local function row_verdict(row, ncols)
    local cells = row.cells
    local first = cells[1] and cells[1].contents
    local code = first and #first == 1 and first[1].content and #first[1].content == 1 and
      first[1].content[1].t == "Code" and first[1].content[1].text
    if not code then
      die(where, "the first cell of each row of a tests box is a test name in backticks, not '" ..
        pandoc.utils.stringify(first or {}) .. "'")
    end
    local at = row_where(run_id, code)
    if #cells ~= ncols then die(at, "the row of `" .. code .. "` has " .. #cells .. " cells, not " .. ncols) end
    if pandoc.utils.stringify(cells[ncols].contents) ~= "" then
      die(at, "the verdict of `" .. code .. "` is the build's to fill: leave the cell empty")
    end
    local verdict = "passed"
    if code:sub(-1) == "*" then
      -- `prefix*` stands for every test whose name starts with prefix (the
      -- checks of one catalog case, `cosine: *`): all of them must pass.
      local prefix, n = code:sub(1, -2), 0
      for name in pairs(failed) do
        if name:sub(1, #prefix) == prefix then
          die(at, "test `" .. name .. "` failed in run '" .. run_id .. "'")
        end
      end
      for name in pairs(ok) do
        if name:sub(1, #prefix) == prefix then n = n + 1 end
      end
      if n == 0 then die(at, "no test matching `" .. code .. "` in the output of run '" .. run_id .. "'") end
      verdict = "passed (" .. n .. ")"
    else
      if failed[code] then die(at, "test `" .. code .. "` failed in run '" .. run_id .. "'") end
      if not ok[code] then die(at, "test `" .. code .. "` is not in the output of run '" .. run_id .. "'") end
    end
    cells[ncols].contents = { pandoc.Plain({ pandoc.Str(verdict) }) }
    append_line(state .. "/test-count", chapter .. " " .. code)
  end
  el.content = el.content:walk({ Table = function(t)
    tables = tables + 1
    -- Natural column widths: a long row would otherwise make pandoc give
    -- every column the same share, the verdict as much as the phrase.
    for i, cs in ipairs(t.colspecs) do t.colspecs[i] = { cs[1], nil } end
    local hrow = t.head.rows[1]
    local ncols = hrow and #hrow.cells or 0
    if ncols < 2 or pandoc.utils.stringify(hrow.cells[ncols].contents):lower() ~= "verdict" then
      die(where, "the last column of a tests box is headed 'verdict'")
    end
    for _, body in ipairs(t.bodies) do
      for _, row in ipairs(body.body) do row_verdict(row, ncols) end
    end
    return t
  end })
  if tables == 0 then die(where, "a tests box holds a pipe table") end
  return el
end

local function div(el)
  if el.classes:includes("tests") then return tests_box(el) end
  return html_only(el)
end

-- The check of the whole tree -------------------------------------------
-- With metadata book-check-regions: every marked region in the files the
-- tree names must have been used (state/used-regions); every file is parsed,
-- so broken markers in a file no chapter includes stop the build too.

local function check_regions()
  local used = {}
  local f = io.open(state .. "/used-regions", "r")
  if f then
    for l in f:lines() do used[l] = true end
    f:close()
  end
  local p = io.popen("cd " .. shell_quote(src_root) ..
    " && grep -rlE 'BEGIN SNIPPET|END SNIPPET' --include='*.c' --include='*.h' --include='*.sh'" ..
    " --include='*.gp' --include='*.awk' --include='*.lua' --include='*.inc' --include=Makefile" ..
    " mc samplers pdf render examples tests bench plots tools Makefile 2>/dev/null | sort")
  local n = 0
  for path in p:lines() do
    local regions = regions_of(path)
    local names = {}
    for name, r in pairs(regions) do names[#names + 1] = { name, r.first } end
    table.sort(names, function(x, y) return x[2] < y[2] end)
    for _, nr in ipairs(names) do
      n = n + 1
      if not used[path .. " " .. nr[1]] then
        die(path .. ":" .. (nr[2] - 1), "region '" .. nr[1] .. "' is used by no chapter")
      end
    end
  end
  p:close()
  io.stdout:write(n .. " marked regions, every one used\n")
end

-- With metadata book-check-citations: every [@key] in a comment of the
-- source tree has an entry, and every entry is cited by a chapter (the
-- HTML pass's state/used-cites) or a comment.
local cite_dirs = "mc samplers pdf render check catalog conform imageio examples tests bench" ..
  " lab exercises outside"

local function check_citations()
  local r = references()
  local cited = {}
  local f = io.open(state .. "/used-cites", "r")
  if f then
    for l in f:lines() do cited[l] = true end
    f:close()
  end
  local p = io.popen("cd " .. shell_quote(src_root) .. " && grep -rnIE '\\[@[A-Za-z0-9_]' " ..
    cite_dirs .. " 2>/dev/null | sort -t: -k1,1 -k2,2n")
  local n = 0
  for l in p:lines() do
    local path, lno, text = l:match("^([^:]+):(%d+):(.*)$")
    for inner in (text or ""):gmatch("%[(@[%w_][^%]]*)%]") do
      for key in inner:gmatch("@([%w_][%w_%-]*)") do
        if not r[key] then
          die(path .. ":" .. lno, "citation [@" .. key .. "] has no entry in " .. refs_name)
        end
        cited[key] = true
        n = n + 1
      end
    end
  end
  p:close()
  local keys = {}
  for key, e in pairs(r) do keys[#keys + 1] = { key, e.line } end
  table.sort(keys, function(x, y) return x[2] < y[2] end)
  for _, ke in ipairs(keys) do
    if not cited[ke[1]] then
      die(refs_name .. ":" .. ke[2], "entry '" .. ke[1] .. "' is cited by no chapter and no comment")
    end
  end
  io.stdout:write(#keys .. " references, every one cited; " .. n .. " citations in comments\n")
end

function Pandoc(doc)
  if doc.meta["book-check-regions"] then
    check_regions()
  end
  if doc.meta["book-check-citations"] then
    check_citations()
  end
  return nil
end

return {
  { CodeBlock = function(el)
      if el.classes:includes("listing") then return listing(el) end
      if el.classes:includes("run") then return run(el) end
      return nil
    end },
  { Cite = cite, Div = reference_entry },
  { Span = function(el)
      if el.classes:includes("num") then return number(el) end
      return nil
    end,
    Image = image,
    Link = link,
    Div = div },
  { Para = para },
  { Pandoc = Pandoc },
}
