:- module(oro_test_support,
          [ test_path/2,                % +Relative, -Path
            test_fixture/2,             % +File, -Path
            test_checkout_path/2,       % +Relative, -Path
            test_child_term/2,          % +Fixture, -Term
            test_store_testsuite/0,
            test_find/4,                % +Model, +Var, +Patterns, -Names
            test_names/2,               % +IRIs, -Names
            test_bool/2,                % :Goal, -Bool
            test_churn_adds/2,          % +Tag, -Reclaimed
            test_reclaimed/2,           % :Goal, -Reclaimed
            test_literal/3,             % +Type, +Lex, -Literal
            test_wait_until/2,          % :Condition, +Seconds
            test_process_wait/3,        % +Pid, -Status, +Seconds
            test_set_text/2,            % +Elements, -Text
            test_server_start/1,        % +Options
            test_server_start_testsuite/0,
            test_server_start_testsuite/1, % +Options
            test_server_start_time_base/2, % +Options, -TimeBase
            test_server_stop/0,
            test_server_stop_synced/0,
            test_server_wait_idle/0,
            test_server_port/1,         % -Port
            test_server_kb_port/1,      % -Port
            test_server_http_port/1,    % -Port
            test_server_connections/1,  % -Count
            test_connected/2,           % -Conn, :Goal
            test_call/3,                % +Method, +Params, ?Reply
            test_calls/2,               % +Requests, ?Replies
            test_receive_n/3,           % +Conn, +N, -Messages
            test_ok/2,                  % +Method, +Params
            test_ok/3,                  % +Method, +Params, -Value
            test_expect_ok/3,           % +Request, +Reply, -Value
            test_error_name/2,          % +Reply, -Name
            test_json/2,                % +Line, -Value
            test_unordered/2,           % +Value, -Sorted
            test_set/2,                 % +Reply, -Set
            test_set_call/3,            % +Method, +Params, -Set
            test_map/2,                 % +Reply, -Pairs
            test_cli_server/4,          % +Args, -Port, :Goal, -Stderr
            test_server_process/5,      % +SwiplArgs, +Dir, -Port, :Goal, -Stderr
            test_log_request/2,         % +Line, -Request
            test_diff/4,                % +Expected, +Actual, +Max, -Diff
            test_first/3,               % +N, +List, -First
            test_seed/2,                % +EnvVar, -Seed
            test_with_setting/3         % +Setting, +Value, :Goal
          ]).
:- reexport(oro_test_client).
:- use_module(library(lists)).
:- use_module(library(ordsets)).
:- use_module(library(apply)).
:- use_module(library(error)).
:- use_module(library(readutil)).
:- use_module(library(process)).
:- use_module(library(http/json)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(settings)).
:- use_module(library(oro)).
:- use_module('../server/oro_server').
:- use_module(library(oro/kbapi/oro_kbapi), [oro_kbapi_connections/2]).

/** <module> Helpers shared by the test files

Every test/test_*.pl is loaded into `user` (test/run_tests.pl loads
them all in one process), so the helpers they all need live here, once:

  - paths relative to the test directory and the checkout, and the
    fixtures under test/fixtures/;
  - a fresh store on the test ontology (test/fixtures/testsuite.ttl);
  - sorted, contracted answers of oro_find/4 and lists of IRIs, and
    typed literal terms;
  - bounded polling (test_wait_until/2);
  - the in-process server of a unit: started on a free port of
    127.0.0.1 in the unit's setup, stopped in its cleanup once its
    workers have seen their clients leave (at most one at a time);
  - requests on their own connection, through test/oro_test_client.pl
    (re-exported), and the value lines of replies (`["a","b"]`,
    `{"k":"v"}`, `[["a","B"]]`) parsed into Prolog terms, sorted where
    the order carries no meaning;
  - the real command line (swipl server/oro_server.pl) as a child
    process;
  - the requests of a recorded ORO server log, for replaying it.

Loading this module also makes library(oro) (test/../prolog) findable,
so a test file loads it first and then `library(oro)` and its
sub-libraries.  Loading starts nothing: no server, no store.
*/

:- multifile user:file_search_path/2.
:- dynamic user:file_search_path/2.

user:file_search_path(library, Lib) :-
    test_dir(Dir),
    atom_concat(Dir, '/../prolog', Lib).

:- dynamic
    test_server/1.                      % Server

:- meta_predicate
    test_bool(0, -),
    test_reclaimed(0, -),
    test_wait_until(0, +),
    test_connected(-, 0),
    test_cli_server(+, -, 0, -),
    test_server_process(+, +, -, 0, -).


                 /*******************************
                 *            PATHS             *
                 *******************************/

%   test_dir(-Dir): the directory of the test files (this file's).

test_dir(Dir) :-
    module_property(oro_test_support, file(File)),
    file_directory_name(File, Dir).

%!  test_path(+Relative, -Path) is det.
%
%   Path is Relative to the test directory (test/), as an atom.

test_path(Relative, Path) :-
    test_dir(Dir),
    atomic_list_concat([Dir, '/', Relative], Path).

%!  test_fixture(+File, -Path) is det.
%
%   Path is File under test/fixtures/.

test_fixture(File, Path) :-
    test_dir(Dir),
    atomic_list_concat([Dir, '/fixtures/', File], Path).

%!  test_checkout_path(+Relative, -Path) is det.
%
%   Path is the absolute name of Relative to the root of the checkout
%   (the parent of test/).

test_checkout_path(Relative, Path) :-
    test_dir(Dir),
    atomic_list_concat([Dir, '/../', Relative], Path0),
    absolute_file_name(Path0, Path).

%!  test_child_term(+Fixture, -Term) is det.
%
%   Run the script Fixture (a path relative to the checkout) in a child
%   process, `swipl -p library=prolog Fixture` (60 s at most), and read
%   the one term it writes on its standard output.  For what only a
%   process that has not loaded everything the tests load can show
%   (which libraries a program loads, a load that fails).  The child
%   must exit with status 0.

test_child_term(Fixture, Term) :-
    test_checkout_path(prolog, Lib),
    test_checkout_path(Fixture, File),
    atom_concat('library=', Lib, LibOption),
    setup_call_cleanup(
        process_create(path(timeout), ['60', swipl, '-p', LibOption, File],
                       [stdout(pipe(Out)), process(Pid)]),
        ( read_term(Out, Term, []),
          process_wait(Pid, Status)
        ),
        close(Out)),
    assertion(Status == exit(0)).


                 /*******************************
                 *          PROLOG API          *
                 *******************************/

%!  test_store_testsuite is det.
%
%   A fresh store holding the test ontology alone
%   (test/fixtures/testsuite.ttl, no common-sense ontology).

test_store_testsuite :-
    test_fixture('testsuite.ttl', File),
    oro_init([commonsense(false), ontologies([File])]).

%!  test_reclaimed(:Goal, -Reclaimed) is det.
%
%   Run Goal (once); Reclaimed is the number of clauses SWI-Prolog's
%   clause garbage collector reclaims once it is done and the watchers
%   have seen its changes: the clauses it retracted (see oro_store,
%   "Writes leave no clause behind").

test_reclaimed(Goal, Reclaimed) :-
    oro_events_sync,
    garbage_collect_clauses,
    statistics(cgc_gained, Before),
    once(Goal),
    oro_events_sync,
    garbage_collect_clauses,
    statistics(cgc_gained, After),
    Reclaimed is After - Before.

%!  test_churn_adds(+Tag, -Reclaimed) is det.
%
%   Add 200 statements to the robot's model, one write each: subjects
%   churn_Tag_I (I in 1..20), `isOn`, objects place_J (J in 1..10).
%   Reclaimed is as for test_reclaimed/2.  Call it once with another
%   Tag first, so that the name cache already holds every name.

test_churn_adds(Tag, Reclaimed) :-
    test_reclaimed(forall(( between(1, 20, I),
                            between(1, 10, J)
                          ),
                          ( format(string(S), "churn_~w_~d isOn place_~d",
                                   [Tag, I, J]),
                            oro_add(myself, [S])
                          )),
                   Reclaimed).

%!  test_find(+Model, +Var, +Patterns, -Names) is det.
%
%   oro_find/4 in Model, the values contracted (oro_term_text/2) and
%   sorted.

test_find(Model, Var, Patterns, Names) :-
    oro_find(Model, Var, Patterns, Values),
    maplist(oro_term_text, Values, Names0),
    sort(Names0, Names).

%!  test_names(+IRIs, -Names) is det.
%
%   Names are the contracted IRIs (oro_iri_name/2), sorted.

test_names(IRIs, Names) :-
    maplist(oro_iri_name, IRIs, Names0),
    sort(Names0, Names).

%!  test_literal(+Type, +Lex, -Literal) is det.
%
%   Literal is the rdf_db typed literal of Lex, Type written with a
%   prefix (xsd:int).

test_literal(Type, Lex, literal(type(IRI, Lex))) :-
    rdf_global_id(Type, IRI).

%!  test_bool(:Goal, -Bool) is det.
%
%   Bool is `true` if Goal succeeds (once), else `false`.

test_bool(Goal, Bool) :-
    (   call(Goal)
    ->  Bool = true
    ;   Bool = false
    ).

%!  test_wait_until(:Condition, +Seconds) is semidet.
%
%   Poll Condition every 10 ms until it holds (true) or Seconds have
%   passed (false).

test_wait_until(Condition, Seconds) :-
    get_time(Now),
    Deadline is Now + Seconds,
    wait_until(Condition, Deadline).

wait_until(Condition, Deadline) :-
    (   call(Condition)
    ->  true
    ;   get_time(Now),
        Now < Deadline
    ->  sleep(0.01),
        wait_until(Condition, Deadline)
    ;   fail
    ).

%!  test_process_wait(+Pid, -Status, +Seconds) is det.
%
%   Status is the exit status of the child process Pid, as of
%   process_wait/2, once it has exited, or `timeout` if it still runs
%   after Seconds.  (SWI-Prolog 9.0.4's process_wait/3 blocks until the
%   child exits whatever its timeout(Seconds) option, but for 0.)

test_process_wait(Pid, Status, Seconds) :-
    (   test_wait_until(exited(Pid, Status0), Seconds)
    ->  Status = Status0
    ;   Status = timeout
    ).

exited(Pid, Status) :-
    process_wait(Pid, Status, [timeout(0)]),
    Status \== timeout.

%!  test_set_text(+Elements, -Text) is det.
%
%   Text is the ORO set of Elements (texts), unquoted, as a request
%   parameter: `[e1, e2, ...]`.

test_set_text(Elements, Text) :-
    must_be(list, Elements),
    atomic_list_concat(Elements, ', ', Inner),
    format(string(Text), "[~w]", [Inner]).

                 /*******************************
                 *       IN-PROCESS SERVER      *
                 *******************************/

%!  test_server_start(+Options) is det.
%
%   Start the unit's server on a free port of 127.0.0.1 with
%   oro_server_start/2 and Options, stopping a leftover one first.

test_server_start(Options) :-
    test_server_stop,
    oro_server_start([port(0), host('127.0.0.1')|Options], Server),
    assertz(test_server(Server)).

%!  test_server_start_testsuite is det.
%
%   The test configuration of ORO-SPEC §13: a server on the test
%   ontology alone.

test_server_start_testsuite :-
    test_server_start_testsuite([]).

%!  test_server_start_testsuite(+Options) is det.
%
%   As test_server_start_testsuite/0, with more options of
%   oro_server_start/2.

test_server_start_testsuite(Options) :-
    test_fixture('testsuite.ttl', File),
    test_server_start([commonsense(false), ontology(File)|Options]).

%!  test_server_start_time_base(+Options, -TimeBase) is det.
%
%   test_server_start/1 with Options, for the tests of memory profiles:
%   TimeBase is the memory time base (ms) the server set (setting
%   oro_memory:time_base), which is then forced to 50 ms whatever it
%   is.

test_server_start_time_base(Options, TimeBase) :-
    test_server_start(Options),
    setting(oro_memory:time_base, TimeBase),
    set_setting(oro_memory:time_base, 50).

%!  test_server_stop is det.
%
%   Stop the unit's server, if any, once its workers have seen their
%   clients leave (test_server_wait_idle/0), so that no worker is still
%   running when the next unit starts or the process halts.  Store
%   rebuilds, which the server turned on, are off again: the tests
%   that follow read the store from their own thread.

test_server_stop :-
    forall(retract(test_server(Server)),
           ( wait_idle(Server),
             oro_server_stop(Server),
             restore_setting(oro_store:rebuild_garbage)
           )).

%!  test_server_stop_synced is det.
%
%   test_server_stop/0, but once the workers are idle, let the watchers
%   see every change (oro_events_sync/0) before stopping the server.

test_server_stop_synced :-
    (   test_server(_)
    ->  test_server_wait_idle,
        oro_events_sync
    ;   true
    ),
    test_server_stop.

%!  test_server_wait_idle is det.
%
%   Wait (10 s at most) until the workers of the unit's server, if
%   any, have seen their clients leave (its KB-API clients too).

test_server_wait_idle :-
    forall(test_server(Server), wait_idle(Server)).

wait_idle(Server) :-
    (   is_dict(Server)
    ->  ignore(test_wait_until(oro_server_connections(Server, 0), 10)),
        (   get_dict(kbapi, Server, KbApi),
            KbApi \== none
        ->  ignore(test_wait_until(oro_kbapi_connections(KbApi, 0), 10))
        ;   true
        )
    ;   true
    ).

%!  test_server_port(-Port) is semidet.
%
%   Port is the port of the unit's server; fails if none runs.

test_server_port(Port) :-
    test_server(Server),
    !,
    oro_server_port(Server, Port).

%!  test_server_kb_port(-Port) is semidet.
%
%   Port is the KB-API port of the unit's server (started with
%   kb_port(0)); fails if none runs or it serves no KB-API.

test_server_kb_port(Port) :-
    test_server(Server),
    !,
    oro_server_kb_port(Server, Port).

%!  test_server_http_port(-Port) is semidet.
%
%   Port is the port of the HTTP side of the unit's server; fails if
%   none runs.

test_server_http_port(Port) :-
    test_server(Server),
    !,
    oro_server_http_port(Server, Port).

%!  test_server_connections(-Count) is semidet.
%
%   Count is the number of connections the unit's server is serving
%   (oro_server_connections/2); fails if none runs.

test_server_connections(Count) :-
    test_server(Server),
    !,
    oro_server_connections(Server, Count).


                 /*******************************
                 *           REQUESTS           *
                 *******************************/

%!  test_connected(-Conn, :Goal) is semidet.
%
%   Run Goal once on a new connection Conn to the unit's server,
%   closed afterwards whatever happens.  Fails if Goal fails or no
%   server runs.

test_connected(Conn, Goal) :-
    test_server_port(Port),
    setup_call_cleanup(
        oro_connect(Port, Conn),
        once(Goal),
        oro_disconnect(Conn)).

%!  test_call(+Method, +Params, ?Reply) is semidet.
%
%   One request on its own connection; Reply as oro_call/4 gives it.
%   Fails if Reply, given, does not match (or no server runs).

test_call(Method, Params, Reply) :-
    test_connected(Conn, oro_call(Conn, Method, Params, Reply)).

%!  test_calls(+Requests, ?Replies) is semidet.
%
%   The Method-Params Requests in order on one connection, Replies as
%   oro_call/4 gives them.  Fails as test_call/3.

test_calls(Requests, Replies) :-
    test_connected(Conn, maplist(request(Conn), Requests, Replies)).

request(Conn, Method-Params, Reply) :-
    oro_call(Conn, Method, Params, Reply).

%!  test_receive_n(+Conn, +N, -Messages) is det.
%
%   Messages are the next N messages on Conn (oro_receive/2), in
%   arrival order.

test_receive_n(Conn, N, Messages) :-
    length(Messages, N),
    maplist(oro_receive(Conn), Messages).

%!  test_ok(+Method, +Params) is det.
%!  test_ok(+Method, +Params, -Value) is det.
%
%   A request that must be answered ok(Value), on its own connection.
%   Any other reply throws test_unexpected_reply(Method-Params, Reply).

test_ok(Method, Params) :-
    test_ok(Method, Params, _).

test_ok(Method, Params, Value) :-
    test_call(Method, Params, Reply),
    test_expect_ok(Method-Params, Reply, Value).

%!  test_expect_ok(+Request, +Reply, -Value) is det.
%
%   Reply is ok(Value); else throw test_unexpected_reply(Request,
%   Reply).

test_expect_ok(_, ok(Value), Value) :-
    !.
test_expect_ok(Request, Reply, _) :-
    throw(test_unexpected_reply(Request, Reply)).

%!  test_error_name(+Reply, -Name) is det.
%
%   Name is the exception name of an error reply, else the reply
%   itself.

test_error_name(Reply, Name) :-
    (   Reply = error(Name0, _)
    ->  Name = Name0
    ;   Name = Reply
    ).


                 /*******************************
                 *            VALUES            *
                 *******************************/

%!  test_json(+Line, -Value) is det.
%
%   Value is the value line Line parsed as JSON: strings as strings,
%   arrays as lists, objects as lists of Key-Value pairs with string
%   keys, sorted by key (standard order).  Throws a syntax error if
%   Line is no JSON.

test_json(Line, Value) :-
    setup_call_cleanup(
        open_string(Line, In),
        json_read_dict(In, JSON, [value_string_as(string)]),
        close(In)),
    json_value(JSON, Value).

json_value(Dict, Pairs) :-
    is_dict(Dict),
    !,
    dict_pairs(Dict, _, Pairs0),
    maplist(json_pair, Pairs0, Pairs1),
    msort(Pairs1, Pairs).
json_value(List0, List) :-
    is_list(List0),
    !,
    maplist(json_value, List0, List).
json_value(Value, Value).

json_pair(Key0-Value0, Key-Value) :-
    atom_string(Key0, Key),
    json_value(Value0, Value).

%!  test_unordered(+Value, -Sorted) is det.
%
%   Sorted is Value (as test_json/2 gives it) with every list, at any
%   depth, sorted with msort/2: for comparing values whose lists carry
%   no order.

test_unordered(List, Sorted) :-
    is_list(List),
    !,
    maplist(test_unordered, List, Items),
    msort(Items, Sorted).
test_unordered(Value, Value).

%!  test_set(+Reply, -Set) is det.
%
%   Reply is ok(List); Set is the list sorted with msort/2 (the order
%   of ORO lists carries no meaning).  Throws if Reply is not `ok` or
%   its value no list.

test_set(Reply, Set) :-
    reply_set(set, Reply, Set).

%!  test_set_call(+Method, +Params, -Set) is det.
%
%   One request answering a list, on its own connection, as
%   test_set/2 gives it.

test_set_call(Method, Params, Set) :-
    test_call(Method, Params, Reply),
    reply_set(Method-Params, Reply, Set).

reply_set(Request, Reply, Set) :-
    test_expect_ok(Request, Reply, Line),
    test_json(Line, List),
    must_be(list, List),
    msort(List, Set).

%!  test_map(+Reply, -Pairs) is det.
%
%   Reply is ok(Map); Pairs are its Key-Value pairs (test_json/2).

test_map(Reply, Pairs) :-
    test_expect_ok(map, Reply, Line),
    test_json(Line, Pairs),
    must_be(list(pair), Pairs).


                 /*******************************
                 *         COMMAND LINE         *
                 *******************************/

%!  test_cli_server(+Args, -Port, :Goal, -Stderr) is det.
%
%   Run the real command line, `swipl server/oro_server.pl Args
%   --port=0` (Args first, as swipl could take them for files to
%   load), as a child process in the checkout (killed after 60 s at
%   most), wait for its listening line, run Goal once, stop the
%   server.  Port is the port it listens on, or `none` (and Goal is not
%   run) if it printed no listening line; Stderr is what it printed on
%   stderr meanwhile.

test_cli_server(Args, Port, Goal, Stderr) :-
    test_checkout_path('server/oro_server.pl', Server),
    test_checkout_path('.', Checkout),
    append(Args, ['--port=0', '--http=0'], AllArgs),
    test_server_process([Server|AllArgs], Checkout, Port, Goal, Stderr).

%!  test_server_process(+SwiplArgs, +Dir, -Port, :Goal, -Stderr) is det.
%
%   As test_cli_server/4, for any server command: run `swipl
%   SwiplArgs` in the directory Dir (killed after 60 s at most), wait
%   for its listening line, run Goal once with Port, stop the server.

test_server_process(SwiplArgs, Dir, Port, Goal, Stderr) :-
    setup_call_cleanup(
        process_create(path(timeout), ['60', swipl|SwiplArgs],
                       [ stdout(pipe(Out)), stderr(pipe(Err)),
                         cwd(Dir), process(Pid)
                       ]),
        ( read_line_to_string(Out, Line),
          (   split_string(Line, ":", " ", Parts),
              last(Parts, PortText),
              number_string(Port, PortText)
          ->  once(Goal)
          ;   Port = none
          )
        ),
        ( process_kill(Pid),
          process_wait(Pid, _),
          read_string(Err, _, Stderr),
          close(Out),
          close(Err)
        )).


                 /*******************************
                 *          SERVER LOGS         *
                 *******************************/

%!  test_log_request(+Line, -Request) is semidet.
%
%   Line of a recorded ORO server log (../shared/workloads/*.log) as a
%   request to replay; fails unless it is a `Got incoming request:
%   Method(Args)` line.  Request is request(Line, Thread, Method,
%   Params): Thread is the text of the line's `[thread N]` tag ("" if it
%   has none), Method a string and Params the arguments, each written
%   back as one line of JSON (a parameter line).  Request is bad(Line)
%   if the arguments do not parse.

test_log_request(Line, Request) :-
    sub_string(Line, _, _, After, "Got incoming request: "),
    !,
    sub_string(Line, _, After, 0, Call),
    (   log_thread(Line, Thread0)
    ->  Thread = Thread0
    ;   Thread = ""
    ),
    (   once(sub_string(Call, Open, _, _, "(")),
        sub_string(Call, 0, Open, _, Method),
        string_concat(Head, ")", Call),
        ArgsStart is Open + 1,
        sub_string(Head, ArgsStart, _, 0, ArgsText),
        atomic_list_concat(['[', ArgsText, ']'], JSON),
        catch(atom_json_term(JSON, Args, [value_string_as(string)]), _, fail),
        is_list(Args),
        maplist(param_line, Args, Params)
    ->  Request = request(Line, Thread, Method, Params)
    ;   Request = bad(Line)
    ).

log_thread(Line, Thread) :-
    once(sub_string(Line, B, _, _, "[thread ")),
    Start is B + 8,
    sub_string(Line, Start, _, 0, Rest),
    once(sub_string(Rest, L, _, _, "]")),
    sub_string(Rest, 0, L, _, Thread).

param_line(Arg, Line) :-
    with_output_to(string(Line),
                   json_write(current_output, Arg, [width(0)])),
    \+ sub_string(Line, _, _, _, "\n").


%!  test_diff(+Expected, +Actual, +Max, -Diff) is det.
%
%   Diff is diff(NMissing, SomeMissing, NExtra, SomeExtra) between two
%   ordered sets: how many elements of Expected are not in Actual and
%   how many of Actual are not in Expected, with at most Max of each
%   listed.  diff(0, [], 0, []) when they are equal.

test_diff(Expected, Actual, Max, diff(NM, SomeM, NE, SomeE)) :-
    ord_subtract(Expected, Actual, Missing),
    ord_subtract(Actual, Expected, Extra),
    length(Missing, NM),
    length(Extra, NE),
    test_first(Max, Missing, SomeM),
    test_first(Max, Extra, SomeE).

%!  test_first(+N, +List, -First) is det.
%
%   First is List, or its first N elements if it has more.

test_first(N, List, First) :-
    length(List, Len),
    (   Len =< N
    ->  First = List
    ;   length(First, N),
        append(First, _, List)
    ).

%!  test_seed(+EnvVar, -Seed) is det.
%
%   The seed of a randomized test: the integer in the environment
%   variable EnvVar (to replay a run), else one taken from the clock.

test_seed(EnvVar, Seed) :-
    (   getenv(EnvVar, Text),
        atom_number(Text, Seed0),
        integer(Seed0)
    ->  Seed = Seed0
    ;   get_time(Now),
        Seed is integer(Now * 1000) mod 1000000007
    ).

%!  test_with_setting(+Setting, +Value, :Goal) is semidet.
%
%   Goal with Setting (a qualified setting name) at Value, restored to
%   its default afterwards.

:- meta_predicate test_with_setting(+, +, 0).

test_with_setting(Setting, Value, Goal) :-
    setup_call_cleanup(set_setting(Setting, Value),
                       Goal,
                       restore_setting(Setting)).
