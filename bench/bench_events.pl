/*  oro events benchmark: latency of pushed events and cost of changes
    with many watchers registered, over the socket.

        swipl bench/bench_events.pl [--samples=200] [--levels=1,100,1000]

    (default levels: 1,100,1000,1000-other; W-other puts the W watchers on
    another predicate)

    It starts the real server (server/oro_server.pl --port=0) as a child
    process and, on one connection, for each level W:

      - resets the server, registers W NEW_INSTANCE watchers with
        distinct patterns `?o isOn shelf_I` (all on the predicate the
        measured changes touch, so every change re-evaluates them all),
        then the measured watcher `?o isOn bench_table`, last, so its
        event comes after all the others have been evaluated;
      - event latency: time from sending `add [objN isOn bench_table]`
        (a new object each sample) to receiving the pushed event
        `["objN"]` (median, p99, and the median of the part after the
        `ok` reply arrived); a sample whose event does not come within
        5 s (or comes with another content) counts as missed;
      - a level W-other registers the W watchers on another predicate
        (`?o isIn box_I`): the changes do not touch them (index by
        predicate);
      - cost of a plain add: round trip of `add` on a predicate no
        watcher uses (`objN hasColor red`) and on the watched one
        (`objN isOn floor`, firing nothing), with W watchers and with
        none (level 0).

    Between phases a registration of an already registered watcher
    serves as a barrier: it is answered once the watcher thread has
    processed every change before it.
*/

:- use_module(library(process)).
:- use_module(library(socket)).
:- use_module(library(readutil)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(main), [argv_options/3]).

:- initialization(main, main).

opt_type(samples, samples, nonneg).
opt_type(levels, levels, term).

:- dynamic bench_dir/1.

:- prolog_load_context(directory, Dir),
   retractall(bench_dir(_)),
   assertz(bench_dir(Dir)).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    (   memberchk(samples(Samples), Options)
    ->  true
    ;   Samples = 200
    ),
    option_levels(Options, Levels),
    machine,
    with_server(Port, bench(Port, Samples, Levels)).

option_levels(Options, Levels) :-
    (   memberchk(levels(Term), Options)
    ->  (   integer(Term)
        ->  Levels = [Term]
        ;   Term = (_,_)
        ->  comma_list(Term, Levels)
        ;   Levels = Term
        )
    ;   Levels = [1, 100, 1000, 1000-other]
    ).

machine :-
    current_prolog_flag(version, V),
    catch(( read_file_to_string('/proc/cpuinfo', CPU, []),
            sub_string(CPU, B, _, _, "model name"),
            sub_string(CPU, B, 80, _, L0),
            split_string(L0, "\n", "", [Line|_])
          ), _, Line = "unknown cpu"),
    format("SWI-Prolog ~w; ~w~n", [V, Line]).

		 /*******************************
		 *            SERVER            *
		 *******************************/

:- meta_predicate with_server(-, 0).

with_server(Port, Goal) :-
    bench_dir(Dir),
    atom_concat(Dir, '/../server/oro_server.pl', Server),
    setup_call_cleanup(
        process_create(path(swipl), [Server, '--port=0'],
                       [stdout(pipe(Out)), process(Pid)]),
        ( read_line_to_string(Out, Line),
          (   split_string(Line, ":", " ", Parts),
              last(Parts, PortText),
              number_string(Port, PortText)
          ->  true
          ;   throw(bench_no_port(Line))
          ),
          once(Goal)
        ),
        ( catch(process_kill(Pid), _, true),
          process_wait(Pid, _),
          close(Out)
        )).

		 /*******************************
		 *            CLIENT            *
		 *******************************/

connect(Port, conn(In, Out)) :-
    tcp_connect('127.0.0.1':Port, Pair, []),
    stream_pair(Pair, In, Out),
    set_stream(In, encoding(utf8)),
    set_stream(In, newline(posix)),
    set_stream(Out, encoding(utf8)),
    set_stream(Out, newline(posix)).

disconnect(conn(In, Out)) :-
    catch(close(Out, [force(true)]), _, true),
    catch(close(In, [force(true)]), _, true).

send(conn(_, Out), Method, Params) :-
    format(Out, "~w~n", [Method]),
    forall(member(P, Params), format(Out, "~w~n", [P])),
    format(Out, "#end#~n", []),
    flush_output(Out).

%   receive(+Conn, -Message, +Timeout): ok(Value), error(Name, Text),
%   event(Id, Content) or timeout.

receive(conn(In, _), Message, Timeout) :-
    (   wait_for_input([In], [_], Timeout)
    ->  read_line_to_string(In, First),
        body(In, Lines),
        message(First, Lines, Message)
    ;   Message = timeout
    ).

body(In, Lines) :-
    read_line_to_string(In, Line),
    (   Line == "#end#"
    ->  Lines = []
    ;   Line == end_of_file
    ->  throw(bench_connection_closed)
    ;   Lines = [Line|Rest],
        body(In, Rest)
    ).

message("ok", [Value], ok(Value)) :- !.
message("ok", [], ok("")) :- !.
message("error", [Name|Text], error(Name, Text)) :- !.
message("event", [Id, Content], event(Id, Content)) :- !.
message(First, Lines, unexpected(First, Lines)).

%   call_ok(+Conn, +Method, +Params, -Value): a request whose next
%   message must be its `ok` (no event is pending when it is used).

call_ok(Conn, Method, Params, Value) :-
    send(Conn, Method, Params),
    receive(Conn, Reply, 30),
    (   Reply = ok(Value)
    ->  true
    ;   throw(bench_failed(Method, Params, Reply))
    ).

call_ok(Conn, Method, Params) :-
    call_ok(Conn, Method, Params, _).

		 /*******************************
		 *            LEVELS            *
		 *******************************/

bench(Port, Samples, Levels) :-
    setup_call_cleanup(
        connect(Port, Conn),
        ( format("~n~w~t~12|~w~t~12+~w~t~14+~w~t~14+~w~t~14+~w~t~8+~w~t~15+~w~n",
                 [watchers, 'register', 'event median', 'event p99',
                  'after ok', missed, 'add unwatched', 'add watched']),
          level(Conn, 0, Samples),
          forall(member(W, Levels), level(Conn, W, Samples))
        ),
        disconnect(Conn)).

level(Conn, Level, Samples) :-
    (   Level = W-other
    ->  Shelf = "[?o isIn box_~d]"
    ;   W = Level,
        Shelf = "[?o isOn shelf_~d]"
    ),
    call_ok(Conn, reset, []),
    register_shelves(Conn, W, Shelf, RegTimes),
    (   W > 0
    ->  measured_pattern(Pattern),
        call_ok(Conn, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", Pattern], Id),
        latencies(Conn, Id, W, Samples, Latencies, AfterOk, Missed),
        barrier(Conn)
    ;   Latencies = [],
        AfterOk = [],
        Missed = '-'
    ),
    add_times(Conn, W, unwatched, Samples, Unwatched),
    barrier(Conn),
    add_times(Conn, W, watched, Samples, Watched),
    barrier(Conn),
    row(Level, RegTimes, Latencies, AfterOk, Missed, Unwatched, Watched).

measured_pattern("[?o isOn bench_table]").

register_shelves(Conn, W, Shelf, Times) :-
    findall(T,
            ( between(1, W, I),
              format(string(P), Shelf, [I]),
              timed(call_ok(Conn, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", P]), T)
            ), Times).

%   barrier(+Conn): returns once every change sent before has been
%   processed by the watcher thread (a registration is queued behind
%   them; this one is a duplicate, so it changes nothing).

barrier(Conn) :-
    measured_pattern(Pattern),
    call_ok(Conn, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", Pattern]).

latencies(Conn, Id, W, Samples, Latencies, AfterOk, Missed) :-
    findall(Result,
            ( between(1, Samples, I),
              latency(Conn, Id, W, I, Result)
            ), Results),
    findall(L, member(L-_, Results), Latencies),
    findall(A, member(_-A, Results), AfterOk),
    exclude(is_pair, Results, MissedList),
    length(MissedList, Missed).

is_pair(_-_).

latency(Conn, Id, W, I, Result) :-
    format(atom(Obj), "obj_~d_~d", [W, I]),
    format(string(Stmt), "[~w isOn bench_table]", [Obj]),
    format(string(Expected), "[\"~w\"]", [Obj]),
    get_time(T0),
    send(Conn, add, [Stmt]),
    receive(Conn, Reply, 30),
    (   Reply = ok(_)
    ->  get_time(TOk),
        receive(Conn, Event, 5),
        get_time(T1),
        (   Event = event(Id, Expected)
        ->  Latency is (T1 - T0) * 1.0e6,
            After is (T1 - TOk) * 1.0e6,
            Result = Latency-After
        ;   Result = missed(Event)
        )
    ;   Result = missed(Reply)
    ).

add_times(Conn, W, Kind, Samples, Times) :-
    findall(T,
            ( between(1, Samples, I),
              add_statement(Kind, W, I, Stmt),
              timed(call_ok(Conn, add, [Stmt]), T)
            ), Times).

add_statement(unwatched, W, I, Stmt) :-
    format(string(Stmt), "[plain_~d_~d hasColor red]", [W, I]).
add_statement(watched, W, I, Stmt) :-
    format(string(Stmt), "[plain_~d_~d isOn floor]", [W, I]).

:- meta_predicate timed(0, -).

timed(Goal, Micros) :-
    get_time(T0),
    once(Goal),
    get_time(T1),
    Micros is (T1 - T0) * 1.0e6.

		 /*******************************
		 *            REPORT            *
		 *******************************/

row(Level, RegTimes, Latencies, AfterOk, Missed, Unwatched, Watched) :-
    median_text(RegTimes, Reg),
    median_text(Latencies, LMed),
    p99_text(Latencies, LP99),
    median_text(AfterOk, AMed),
    median_text(Unwatched, UMed),
    median_text(Watched, WMed),
    (   Level = W-other
    ->  format(string(Label), "~d (isIn)", [W])
    ;   format(string(Label), "~d", [Level])
    ),
    format("~w~t~12|~w~t~12+~w~t~14+~w~t~14+~w~t~14+~w~t~8+~w~t~15+~w~n",
           [Label, Reg, LMed, LP99, AMed, Missed, UMed, WMed]),
    flush_output.

median_text([], "-") :- !.
median_text(Times, Text) :-
    msort(Times, Sorted),
    length(Sorted, N),
    M is N // 2,
    nth0(M, Sorted, X),
    micros(X, Text).

p99_text([], "-") :- !.
p99_text(Times, Text) :-
    msort(Times, Sorted),
    length(Sorted, N),
    P is min(N - 1, (N * 99) // 100),
    nth0(P, Sorted, X),
    micros(X, Text).

micros(X, Text) :-
    format(string(Text), "~1f us", [X]).
