/*  oro web inspector benchmark: every page at a robot's scale, and the
    live feed under a steady stream of changes.

        swipl bench/bench_inspector.pl [--size=100000] [--agents=50]
              [--watchers=1000] [--samples=20] [--rate=1000] [--seconds=5]

    The robot's model holds bench.pl's synthetic world of about Size
    triples (over the common-sense ontology) and 1,000 short-term facts;
    Agents agent models hold 20 facts each; Watchers watchers are spread
    over the models (one in 50 on the robot's).  A server runs in this
    process, its HTTP side on a free port.

    Pages: "http" is the time to fetch, one after the other, what the
    page's script fetches (the shell, its script and style sheet, and its
    JSON) over HTTP from this process; "browser" the time headless
    chromium takes from navigation until the page has drawn its data
    (skipped without chromium).  Feed: Rate changes a second (one fact
    per add) for Seconds, one websocket client: what it received, what
    it was told was dropped, the batches, and the delay from the last
    add to its arrival.  Prints one table of each.  "subclasses" (a
    class opened in the tree) and "explain" (a "why" link) are fetches
    of a page already shown: no browser time.
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)),
   asserta(user:file_search_path(oro_bench, Dir)).

:- use_module(library(oro)).
:- use_module(library(oro/http/oro_http_feed)).
:- use_module(library(option)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(uri)).
:- use_module(library(readutil)).
:- use_module(library(http/http_open)).
:- use_module(library(http/websocket)).
:- use_module(library(main), [argv_options/3]).
:- use_module(oro_bench('../server/oro_server')).
:- use_module(oro_bench('../test/oro_test_browser')).
:- use_module(bench_common).

:- initialization(main, main).

opt_type(size, size, nonneg).
opt_type(agents, agents, nonneg).
opt_type(watchers, watchers, nonneg).
opt_type(samples, samples, nonneg).
opt_type(rate, rate, nonneg).
opt_type(seconds, seconds, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(size(Size), Options, 100000),
    option(agents(Agents), Options, 50),
    option(watchers(Watchers), Options, 1000),
    option(samples(Samples), Options, 20),
    option(rate(Rate), Options, 1000),
    option(seconds(Seconds), Options, 5),
    bench_machine,
    setup_call_cleanup(
        oro_server_start([port(0), host('127.0.0.1'), http(0)], Server),
        ( oro_server_http_port(Server, Port),
          load_world(Size, Agents, Watchers, Asserted),
          format("~D triples asserted in the robot's model, ~D agent models, \c
                  ~D watchers~n", [Asserted, Agents, Watchers]),
          bench_pages(Port, Samples),
          bench_feed(Port, Rate, Seconds)
        ),
        oro_server_stop(Server)).

		 /*******************************
		 *           THE WORLD          *
		 *******************************/

load_world(Size, Agents, Watchers, Asserted) :-
    bench_world(Size, Statements),
    bench_batches(Statements, 1000, Batches),
    forall(member(B, Batches), oro_add(myself, B)),
    findall(S, ( between(1, 1000, I),
                 format(string(S), "obj~d isNear furniture~d", [I, I mod 50])
               ), Short),
    oro_add(myself, Short, shortterm),
    forall(between(1, Agents, A),
           ( format(atom(Agent), 'agent~d', [A]),
             oro_create_agent(Agent, Agent),
             findall(S, ( between(1, 20, I),
                          format(string(S), "obj~d isVisible true", [A*20+I])
                        ), Facts),
             oro_add(Agent, Facts)
           )),
    findall(M, ( between(1, Agents, A), format(atom(M), 'agent~d', [A]) ), Ms),
    Models = [myself|Ms],
    length(Models, NM),
    forall(between(1, Watchers, W),
           ( (   W mod 50 =:= 0
             ->  Model = myself
             ;   I is W mod NM,
                 nth0(I, Models, Model)
             ),
             F is W mod 50,
             format(string(P), "?x isOn furniture~d", [F]),
             oro_subscribe(Model, 'NEW_INSTANCE', 'ON_TRUE', x, [P],
                           ignore_event, _)
           )),
    oro_events_sync,
    oro_store:oro_asserted_count(myself, Asserted).

ignore_event(_, _).

		 /*******************************
		 *            PAGES             *
		 *******************************/

%   page(?Name, ?Path, ?Fetches): a page, and the JSON its script
%   fetches (each page's select of models fetches /api/models too).

page(overview,   '/',                        ['/api/overview', '/api/models']).
page(classes,    '/classes',                 ['/api/classes', '/api/models']).
page(subclasses, '/classes',                 ['/api/classes?class=http%3A%2F%2Fkb.openrobots.org%23Artifact']).
page(lookup,     '/classes?q=obj1',          ['/api/lookup?q=obj1', '/api/models']).
page(resource,   '/resource?iri=http%3A%2F%2Fkb.openrobots.org%23obj1',
                 ['/api/resource?iri=http%3A%2F%2Fkb.openrobots.org%23obj1', '/api/models']).
page(hub,        '/resource?iri=http%3A%2F%2Fkb.openrobots.org%23furniture1',
                 ['/api/resource?iri=http%3A%2F%2Fkb.openrobots.org%23furniture1', '/api/models']).
page(explain,    '/resource?iri=http%3A%2F%2Fkb.openrobots.org%23obj1',
                 ['/api/explain?s=http%3A%2F%2Fkb.openrobots.org%23obj1&p=http%3A%2F%2Fwww.w3.org%2F1999%2F02%2F22-rdf-syntax-ns%23type&o=http%3A%2F%2Fkb.openrobots.org%23Artifact']).
page(graph,      '/graph?iri=http%3A%2F%2Fkb.openrobots.org%23obj1',
                 ['/api/graph?iri=http%3A%2F%2Fkb.openrobots.org%23obj1&hops=2', '/api/models']).
page(feed,       '/feed',                    ['/api/models']).
page(query,      '/query',                   ['/sparql?query=PREFIX%20oro%3A%20%3Chttp%3A%2F%2Fkb.openrobots.org%23%3E%20SELECT%20%3Fp%20%3Fo%20WHERE%20%7B%20oro%3Amyself%20%3Fp%20%3Fo%20%7D', '/api/models']).

bench_pages(Port, Samples) :-
    (   browser_available
    ->  browser_start(Browser)
    ;   Browser = none
    ),
    format("~n~w~t~14|~w~t~14+~w~t~12+~w~t~12+~w~t~12+~w~t~12+~w~n",
           [page, 'http median', 'http p99', 'browser med', 'browser p99',
            'JSON bytes', 'http max']),
    forall(page(Name, Path, Fetches),
           bench_page(Port, Browser, Samples, Name, Path, Fetches)),
    (   Browser == none
    ->  format("(no chromium: browser times skipped)~n")
    ;   browser_stop(Browser)
    ).

bench_page(Port, Browser, Samples, Name, Path, Fetches) :-
    append([Path, '/web/inspector.js', '/web/inspector.css'], Fetches, All),
    findall(T-Bytes, ( between(1, Samples, _),
                       fetch_all(Port, All, T, Bytes)
                     ), Pairs),
    pairs_keys_values(Pairs, Times, [Bytes|_]),
    bench_summary(Times, Median, P99),
    max_list(Times, Max),
    (   ( Browser == none ; Name == explain ; Name == subclasses )
    ->  BMedian = "-", BP99 = "-"
    ;   format(atom(URL), 'http://127.0.0.1:~w~w', [Port, Path]),
        BSamples is max(3, Samples // 4),
        findall(BT, ( between(1, BSamples, _),
                      browser_load(Browser, URL, BT)
                    ), BTimes),
        bench_summary(BTimes, BM, BP),
        format(string(BMedian), "~1f ms", [BM]),
        format(string(BP99), "~1f ms", [BP])
    ),
    format("~w~t~14|~1f ms~t~14+~1f ms~t~12+~w~t~12+~w~t~12+~D~t~12+~1f ms~n",
           [Name, Median, P99, BMedian, BP99, Bytes, Max]).

fetch_all(Port, Paths, Ms, Bytes) :-
    get_time(T0),
    maplist(fetch_size(Port), Paths, Sizes),
    get_time(T1),
    Ms is (T1 - T0) * 1000,
    nth1(4, Sizes, Bytes).

fetch_size(Port, Path, Len) :-
    format(atom(URL), 'http://127.0.0.1:~w~w', [Port, Path]),
    setup_call_cleanup(
        http_open(URL, In, [status_code(Status), timeout(60)]),
        read_string(In, Len, _),
        close(In)),
    (   Status == 200
    ->  true
    ;   throw(error(bench_http_status(URL, Status), _))
    ).

browser_load(Browser, URL, Ms) :-
    get_time(T0),
    browser_open(Browser, URL, Ready),
    get_time(T1),
    (   Ready == true
    ->  true
    ;   throw(error(bench_page_not_drawn(URL, Ready), _))
    ),
    Ms is (T1 - T0) * 1000.

		 /*******************************
		 *             FEED             *
		 *******************************/

bench_feed(Port, Rate, Seconds) :-
    format(atom(URL), 'ws://127.0.0.1:~w/api/feed', [Port]),
    N is Rate * Seconds,
    setup_call_cleanup(
        http_open_websocket(URL, WS, []),
        ( set_stream(WS, timeout(30)),
          wait_clients,
          thread_create(writer(Rate, N), Writer, []),
          get_time(T0),
          read_feed(WS, N, 0, 0, 0, Received, Dropped, Batches),
          get_time(T1),
          thread_join(Writer, WriterStatus)
        ),
        catch(ws_close(WS, 1000, ""), _, true)),
    (   WriterStatus = exited(Sent-Delay0)
    ->  Delay is (T1 - Delay0) * 1000
    ;   Sent = WriterStatus,
        Delay = 0
    ),
    Elapsed is T1 - T0,
    PerSecond is Received / Elapsed,
    format("~n~w~t~16|~w~t~10+~w~t~10+~w~t~10+~w~t~10+~w~t~14+~w~n",
           ['feed', sent, received, dropped, batches, 'received/s',
            'last delay']),
    format("~w~t~16|~D~t~10+~D~t~10+~D~t~10+~D~t~10+~0f~t~14+~1f ms~n",
           ['1 client', Sent, Received, Dropped, Batches, PerSecond, Delay]).

wait_clients :-
    oro_feed_stats(S),
    (   S.clients >= 1
    ->  true
    ;   sleep(0.01),
        wait_clients
    ).

%   writer(+Rate, +N): add N facts, one per add, Rate a second; exits
%   with the number sent and the time of the last add.

writer(Rate, N) :-
    get_time(T0),
    writer(1, N, Rate, T0),
    get_time(T1),
    thread_exit(N-T1).

writer(I, N, Rate, T0) :-
    (   I > N
    ->  true
    ;   format(string(S), "fed~d isOn furniture~d", [I, I mod 50]),
        oro_add(myself, [S]),
        Due is T0 + I / Rate,
        get_time(Now),
        (   Due > Now
        ->  Sleep is Due - Now,
            sleep(Sleep)
        ;   true
        ),
        I1 is I + 1,
        writer(I1, N, Rate, T0)
    ).

read_feed(WS, N, R0, D0, B0, R, D, B) :-
    (   R0 + D0 >= N
    ->  R = R0, D = D0, B = B0
    ;   ws_receive(WS, Message, [format(json)]),
        Data = Message.data,
        (   is_dict(Data)
        ->  include(fed_change, Data.changes, Fed),
            length(Fed, NF),
            R1 is R0 + NF,
            D1 is D0 + Data.dropped,
            B1 is B0 + 1
        ;   R1 = R0, D1 = D0, B1 = B0
        ),
        read_feed(WS, N, R1, D1, B1, R, D, B)
    ).

fed_change(C) :-
    sub_atom(C.s, 0, _, _, fed).
