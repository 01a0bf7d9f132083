/*  Tests of the web inspector (prolog/oro/http/oro_http_inspector.pl and
    oro_http_feed.pl): its JSON API and pages by real HTTP requests, its
    live feed by a real websocket, and every page in a real browser
    (Debian's chromium, headless, driven over DevTools: see
    oro_test_browser.pl), on a server of an ephemeral loopback port.
    The browser's screenshots are kept in /tmp/oro-inspector-shots/.
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(oro_test_browser).
:- use_module(library(http/http_open)).
:- use_module(library(http/json)).
:- use_module(library(http/websocket)).
:- use_module(library(readutil)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(uri)).
:- use_module(library(settings)).
:- use_module(library(oro)).
:- use_module(library(oro/http/oro_http_inspector)).
:- use_module(library(oro/http/oro_http_feed)).
:- use_module('../server/oro_server').

%   in_start: the unit's server, HTTP side on a free port, test
%   ontology, a monkey on a tree, an agent.

in_start :-
    test_server_start_testsuite([http(0)]),
    oro_add(myself, ["zork rdf:type Monkey", "zork isOn tree1",
                     "zork rdfs:label \"Zork\"@en"]),
    oro_create_agent(bob, bob),
    test_ok(addForAgent, [bob, '[zork rdf:type Animal]']).

in_stop :-
    set_setting(oro_http_feed:queue_size, 20000),
    oro_feed_stop,
    test_server_stop.

%   in_get(+PathAndQuery, -Status, -Body): one GET on the unit's server.

in_get(Path, Status, Body) :-
    test_server_http_port(Port),
    format(atom(URL), 'http://127.0.0.1:~w~w', [Port, Path]),
    setup_call_cleanup(
        http_open(URL, In, [status_code(Status), timeout(30)]),
        ( set_stream(In, encoding(utf8)),
          read_string(In, _, Body)
        ),
        close(In)).

%   in_api(+Path, +Params, -Status, -Dict): one call of /api/Path.

in_api(Path, Params, Status, Dict) :-
    uri_query_components(Search, Params),
    format(atom(P), '/api/~w?~w', [Path, Search]),
    in_get(P, Status, Body),
    atom_json_dict(Body, Dict, [value_string_as(atom)]).

iri(Local, IRI) :-
    atom_concat('http://kb.openrobots.org#', Local, IRI).

:- begin_tests(inspector_api, [setup(in_start), cleanup(in_stop)]).

test(overview, [true(Names-Conn == [bob, myself]-0)]) :-
    in_api(overview, [], 200, O),
    maplist([M, N]>>(N = M.name), O.models, Names),
    member(M, O.models),
    M.name == myself,
    !,
    assertion(M.triples.longterm >= 3),
    assertion(M.triples.shortterm == 0),
    Conn = O.connections.

test(overview_watchers_deadlines, [true(W-D-First == 1-1-lunch)]) :-
    oro_subscribe(myself, 'NEW_INSTANCE', 'ON_TRUE', x, ["?x rdf:type Monkey"],
                  ignore_event, _),
    test_ok(add, ['[lunch rdf:type Banana]', 'SHORTTERM']),
    in_api(overview, [], 200, O),
    W = O.watcher_count,
    D = O.deadline_count,
    [Dl] = O.deadlines,
    First = Dl.statement.s.name.

test(class_tree, [true(Animal == N-2)]) :-
    iri('Animal', A),
    oro_instances(myself, A, Is),
    length(Is, N),
    in_api(classes, [], 200, Root),
    member(C, Root.children),
    C.class.iri == A,
    !,
    in_api(classes, [class=A], 200, Sub),
    member(Monkey, Sub.children),
    Monkey.class.name == 'Monkey',
    !,
    Animal = C.instances-C.subclasses,
    iri('Monkey', MonkeyClass),
    oro_instances(myself, MonkeyClass, Monkeys),
    length(Monkeys, NM),
    assertion(Monkey.instances == NM).

test(lookup, [true(Names == [zork])]) :-
    in_api(lookup, [q='Zork'], 200, R),
    maplist([M, N]>>(N = M.term.name), R.matches, Names).

test(resource_asserted_inferred) :-
    iri(zork, Z),
    in_api(resource, [iri=Z], 200, R),
    maplist(triple_names, R.asserted, Asserted),
    maplist(triple_names, R.inferred, Inferred),
    assertion(memberchk(zork-'rdf:type'-'Monkey', Asserted)),
    assertion(\+ memberchk(zork-'rdf:type'-'Animal', Asserted)),
    assertion(memberchk(zork-'rdf:type'-'Animal', Inferred)),
    assertion(memberchk(tree1-isUnder-zork, Inferred)),
    assertion(\+ memberchk(zork-'rdf:type'-'Monkey', Inferred)),
    assertion(R.label == 'Zork'),
    maplist([V, M-K]>>(M = V.model, K = V.known), R.models, Known),
    assertion(Known == [bob-true, myself-true]).

test(explain, [true(Facts == [zork-'rdf:type'-'Monkey'])]) :-
    iri(zork, Z),
    iri('Animal', A),
    in_api(explain, [s=Z, p='http://www.w3.org/1999/02/22-rdf-syntax-ns#type',
                     o=A], 200, W),
    W.holds == true,
    maplist([F, T]>>triple_names(F.statement, T), W.facts, Facts).

test(explain_not_holding, [true(H == false)]) :-
    iri(zork, Z),
    iri('Plant', P),
    in_api(explain, [s=Z, p='http://www.w3.org/1999/02/22-rdf-syntax-ns#type',
                     o=P], 200, W),
    H = W.holds.

test(graph, [true(Names == [zork, 'Monkey', tree1])]) :-
    iri(zork, Z),
    in_api(graph, [iri=Z, hops=2], 200, G),
    maplist([N, Name]>>(Name = N.name), G.nodes, Names0),
    msort(Names0, Sorted),
    msort([zork, 'Monkey', tree1], Sorted),
    Names = [zork, 'Monkey', tree1],
    assertion(length(G.edges, 2)).

test(unknown_model, [true(S == 404)]) :-
    in_api(resource, [iri=x, model=nobody], S, E),
    assertion(atom(E.error)).

test(unknown_resource, [true(S == 404)]) :-
    in_api(resource, [iri='http://example.org/nothing'], S, _).

test(missing_parameter, [true(S == 400)]) :-
    in_api(graph, [], S, _).

test(bad_hops, [true(S == 400)]) :-
    iri(zork, Z),
    in_api(graph, [iri=Z, hops=9], S, _).

test(pages, [true(Statuses == [200, 200, 200, 200, 200, 200, 200, 200])]) :-
    maplist([P, S]>>in_get(P, S, _),
            ['/', '/classes', '/resource', '/graph', '/feed', '/query',
             '/web/inspector.js', '/web/inspector.css'], Statuses).

test(no_other_file, [true(S == 404)]) :-
    in_get('/web/../oro_http.pl', S, _).

:- end_tests(inspector_api).

triple_names(T, S-P-O) :-
    S = T.s.name,
    P = T.p.name,
    (   get_dict(name, T.o, O)
    ->  true
    ;   O = T.o.literal
    ).

		 /*******************************
		 *          LIVE FEED           *
		 *******************************/

%   with_feed(+Params, -WS, :Goal): Goal with a feed websocket open.

with_feed(Params, WS, Goal) :-
    test_server_http_port(Port),
    uri_query_components(Search, Params),
    format(atom(URL), 'ws://127.0.0.1:~w/api/feed?~w', [Port, Search]),
    setup_call_cleanup(
        http_open_websocket(URL, WS, []),
        ( set_stream(WS, timeout(10)),
          test_wait_until(feed_clients_at_least(1), 10),
          call(Goal)
        ),
        catch(ws_close(WS, 1000, ""), _, true)).

feed_clients_at_least(N) :-
    oro_feed_stats(Stats),
    Stats.clients >= N.

%   feed_until(+WS, :Test, -Batches): read batches until one passes
%   Test (10 s at most, else fail).

feed_until(WS, Test, Batches) :-
    get_time(T0),
    Deadline is T0 + 10,
    feed_until(WS, Test, Deadline, Batches).

feed_until(WS, Test, Deadline, [Batch|Batches]) :-
    get_time(Now),
    Now < Deadline,
    ws_receive(WS, Message, [format(json), value_string_as(atom)]),
    (   Message.opcode == text
    ->  Batch = Message.data
    ;   Batch = _{changes:[], events:[], commits:[], dropped:0}
    ),
    (   call(Test, Batch)
    ->  Batches = []
    ;   feed_until(WS, Test, Deadline, Batches)
    ).

mentions(Name, Batch) :-
    member(C, Batch.changes),
    C.s == Name.

has_events(Batch) :-
    Batch.events \== [].

dropped(Batch) :-
    Batch.dropped > 0.

:- begin_tests(inspector_feed, [setup(in_start), cleanup(in_stop)]).

test(change) :-
    with_feed([], WS,
              ( test_ok(add, ['[fed1 rdf:type Banana]']),
                feed_until(WS, mentions(fed1), Batches)
              )),
    last(Batches, Last),
    member(C, Last.changes),
    C.s == fed1,
    !,
    assertion(C.op == add),
    assertion(C.model == myself),
    assertion(C.profile == longterm),
    assertion(C.o == 'Banana').

test(event_fired) :-
    oro_subscribe(myself, 'NEW_INSTANCE', 'ON_TRUE', x, ["?x rdf:type Plant"],
                  ignore_event, _),
    with_feed([], WS,
              ( test_ok(add, ['[fern1 rdf:type Plant]']),
                feed_until(WS, has_events, Batches)
              )),
    last(Batches, Last),
    Last.events = [E|_],
    assertion(E.model == myself),
    assertion(sub_atom(E.content, _, _, _, fern1)).

test(filter_by_model) :-
    with_feed([model=bob], WS,
              ( test_ok(add, ['[notbob1 rdf:type Banana]']),
                test_ok(addForAgent, [bob, '[bob1 rdf:type Banana]']),
                feed_until(WS, mentions(bob1), Batches)
              )),
    forall(( member(B, Batches), member(C, B.changes) ),
           assertion(C.model == bob)).

test(says_when_it_drops, [cleanup(oro_feed_stop)]) :-
    set_setting(oro_http_feed:queue_size, 1),
    oro_feed_stop,                      % the next hub has a queue of 1
    findall(S, ( between(1, 2000, I),
                 format(string(S), "drop~w rdf:type Banana", [I])
               ), Statements),
    with_feed([], WS,
              ( with_mutex(oro_inspector_feed_hub,      % hold the hub back
                           oro_add(myself, Statements)),
                feed_until(WS, dropped, _)
              )).

:- end_tests(inspector_feed).

ignore_event(_, _).

		 /*******************************
		 *           BROWSER            *
		 *******************************/

shots_dir('/tmp/oro-inspector-shots').

br_start :-
    in_start,
    oro_add(myself, ["zork eats banana1", "banana1 rdf:type Banana"]),
    browser_start(B),
    nb_setval(oro_test_browser, B).

br_stop :-
    nb_getval(oro_test_browser, B),
    browser_stop(B),
    nb_setval(oro_test_browser, none),
    in_stop.

browser(B) :-
    nb_getval(oro_test_browser, B).

%   open_page(+Name, +Path): load the page in the browser, check that
%   it drew itself without an error, and keep its screenshot.

open_page(Name, Path) :-
    browser(B),
    test_server_http_port(Port),
    format(atom(URL), 'http://127.0.0.1:~w~w', [Port, Path]),
    browser_open(B, URL, Ready),
    assertion(Ready == true),
    browser_errors(B, Errors),
    assertion(Errors == []),
    shot(Name, Distinct),
    assertion(Distinct > 64).

%   open_page(+Name, +Path, +Local): open_page/2 of Path followed by
%   the IRI of Local, encoded.

open_page(Name, Path, Local) :-
    iri(Local, IRI),
    uri_encoded(query_value, IRI, Q),
    atom_concat(Path, Q, PathQ),
    open_page(Name, PathQ).

shot(Name, Distinct) :-
    browser(B),
    shots_dir(Dir),
    make_directory_path(Dir),
    format(atom(File), '~w/~w.png', [Dir, Name]),
    browser_screenshot(B, File, Distinct).

text_in_page(Id, Text) :-
    browser(B),
    format(string(JS), "(document.getElementById('~w') || {}).textContent || ''",
           [Id]),
    browser_eval(B, JS, Content),
    sub_string(Content, _, _, _, Text).

:- begin_tests(inspector_browser,
               [ condition(browser_present),
                 setup(br_start),
                 cleanup(br_stop)
               ]).

browser_present :-
    (   browser_available
    ->  true
    ;   print_message(informational,
                      format('No chromium: the inspector\'s browser tests are skipped', [])),
        fail
    ).

test(blank_screenshot_is_blank) :-
    browser(B),
    browser_open(B, 'data:text/html,<body data-ready="true"></body>', Ready),
    assertion(Ready == true),
    shot('blank-reference', Distinct),
    assertion(Distinct =< 64).

test(overview) :-
    open_page(overview, '/'),
    assertion(text_in_page('card-models', "2")).

test(classes) :-
    open_page(classes, '/classes'),
    assertion(text_in_page(tree, "Animal")).

test(lookup) :-
    open_page(lookup, '/classes?q=zork'),
    assertion(text_in_page(main, "instance")).

test(resource) :-
    open_page(resource, '/resource?iri=', zork),
    assertion(text_in_page(main, "Inferred statements")),
    assertion(text_in_page(main, "isUnder")),
    browser(B),
    browser_eval(B, "document.querySelector('a.why').click(), true", _),
    assertion(test_wait_until(text_in_page(main, "Facts:"), 10)),
    shot('resource-why', _),
    browser_errors(B, Errors),
    assertion(Errors == []).

test(graph) :-
    open_page(graph, '/graph?iri=', zork),
    assertion(text_in_page(graph, "banana1")).

test(query) :-
    uri_encoded(query_value,
                "PREFIX oro: <http://kb.openrobots.org#>\n\c
                 SELECT ?p ?o WHERE { oro:zork ?p ?o }", Q),
    atom_concat('/query?query=', Q, Path),
    open_page(query, Path),
    assertion(text_in_page(results, "rows")),
    assertion(text_in_page(results, "http://kb.openrobots.org#tree1")).

test(feed_shows_a_fact_within_a_second) :-
    open_page('feed-empty', '/feed'),
    assertion(test_wait_until(text_in_page(feedstatus, "live"), 10)),
    assertion(test_wait_until(feed_clients_at_least(1), 10)),
    test_ok(add, ['[browsed1 rdf:type Banana]']),
    assertion(test_wait_until(text_in_page(feedlog, "browsed1"), 1)),
    shot(feed, Distinct),
    assertion(Distinct > 64),
    browser(B),
    browser_errors(B, Errors),
    assertion(Errors == []).

:- end_tests(inspector_browser).
