:- use_module(library(plunit)).
:- use_module(library(socket)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(error)).
:- use_module(library(settings)).
:- use_module(library(pairs)).
:- use_module(library(yall)).
:- use_module(oro_test_support).
:- use_module(oro_test_client).
:- use_module('../server/oro_server').
:- use_module(library(oro)).

/*  Where a connection's events are written among its replies (README,
    "Clients"; prolog/oro/server/oro_methods.pl, CONNECTION EVENTS), what
    clearEvents removes, and the minimum reply latency for unpatched
    liboro builds (server/oro_server.pl, MINIMUM REPLY LATENCY).

    events_liboro drives the server with a client that reads as liboro
    1.3.1 reads (lib_call/4): the first line of a message may be waited
    for, but once it has read an event while it waits for a reply, the
    next message must already be in its buffer (liboro then reads
    without waiting and takes an empty buffer for a lost connection),
    and every line after the first of a message too.  After a reply it
    reads the events already buffered, as liboro's listener thread
    does, then sends its next request.

    Run: swipl test/run_tests.pl test_event_order
*/

                 /*******************************
                 *      A LIBORO-LIKE CLIENT    *
                 *******************************/

%   eo_fresh: the store as loaded, no watcher, no connection left over.

eo_fresh :-
    test_server_wait_idle,
    oro_reset.

%   lib_connect(+Port, +Mode, -Lib): Lib is lib(In, Out, State, Mode),
%   State holding the replies read so far, the events read (newest
%   first, as Content-RepliesBefore) and whether the connection was
%   lost.  Mode `listen` reads the events already buffered after each
%   reply before the next request, as liboro's listener thread does
%   when it runs first; `eager` sends the next request at once, as
%   liboro does when its calling thread runs first (the listener then
%   reads a left-over event while a reply is awaited).

lib_connect(Port, Mode, lib(In, Out, State, Mode)) :-
    tcp_connect('127.0.0.1':Port, Pair, [nodelay(true)]),
    stream_pair(Pair, In, Out),
    set_stream(In, encoding(utf8)),
    set_stream(Out, encoding(utf8)),
    State = state(0, [], connected).

lib_close(lib(In, Out, _, _)) :-
    catch(close(Out, [force(true)]), _, true),
    catch(close(In, [force(true)]), _, true).

%   lib_call(+Lib, +Method, +Params, -Reply): Reply is ok(Line),
%   error(Name) or lost (the client would have reported "Peer
%   deconnection").

lib_call(Lib, Method, Params, Reply) :-
    Lib = lib(_, Out, State, Mode),
    (   arg(3, State, lost)
    ->  Reply = lost
    ;   atomic_list_concat([Method|Params], '\n', Head),
        format(Out, "~w~n#end#~n", [Head]),
        flush_output(Out),
        lib_reply(Lib, wait, Reply),
        (   Reply == lost
        ->  nb_setarg(3, State, lost)
        ;   arg(1, State, N0),
            N is N0 + 1,
            nb_setarg(1, State, N),
            (   Mode == listen
            ->  lib_listen(Lib)
            ;   true
            )
        )
    ).

%   lib_reply(+Lib, +Wait, -Reply): read messages until a reply; Wait
%   is `wait` for the first (10 s at most), `buffered` after an event.

lib_reply(Lib, Wait, Reply) :-
    lib_message(Lib, Wait, Message),
    (   Message = event(Content)
    ->  lib_note_event(Lib, Content),
        lib_reply(Lib, buffered, Reply)
    ;   Reply = Message
    ).

%   lib_listen(+Lib): read the events already buffered.

lib_listen(Lib) :-
    Lib = lib(In, _, State, _),
    (   wait_for_input([In], [_], 0)
    ->  lib_message(Lib, buffered, Message),
        (   Message = event(Content)
        ->  lib_note_event(Lib, Content),
            lib_listen(Lib)
        ;   nb_setarg(3, State, lost)       % a reply nobody waited for
        )
    ;   true
    ).

lib_note_event(lib(_, _, State, _), Content) :-
    arg(1, State, Replies),
    arg(2, State, Events),
    nb_setarg(2, State, [Content-Replies|Events]).

%   lib_message(+Lib, +Wait, -Message): event(Content), ok(Line),
%   error(Name) or lost.

lib_message(lib(In, _, _, _), Wait, Message) :-
    (   Wait == wait
    ->  wait_for_input([In], Ready, 10)
    ;   wait_for_input([In], Ready, 0)
    ),
    (   Ready == []
    ->  Message = lost
    ;   lib_lines(In, Lines),
        (   Lines = ["event", _, Content]
        ->  Message = event(Content)
        ;   Lines = ["ok", Line]
        ->  Message = ok(Line)
        ;   Lines = ["error", Name|_]
        ->  Message = error(Name)
        ;   Message = lost
        )
    ).

%   lib_lines(+In, -Lines): the lines of one message, up to #end#; a
%   line not buffered yet (after the first) loses the connection.

lib_lines(In, Lines) :-
    read_line_to_string(In, Line),
    (   Line == end_of_file
    ->  Lines = []
    ;   Line == "#end#"
    ->  Lines = []
    ;   Lines = [Line|Rest],
        (   wait_for_input([In], [_], 0)
        ->  lib_lines(In, Rest)
        ;   Rest = [lost]
        )
    ).

                 /*******************************
                 *            LIBORO            *
                 *******************************/

%   lib_cups(+Lib, +N, -Result): N iterations of add a Cup, then find,
%   after registering a NEW_CLASS_INSTANCE watcher on Cup: Result is
%   result(Lost, Late, Received, Wrong), Lost 1 if the connection was
%   lost, Late the cups whose event was not read when the reply to the
%   find after their add came, Received the events read, Wrong the cups
%   whose event is missing or came twice.

lib_cups(Lib, N, result(Lost, Late, Received, Wrong)) :-
    lib_call(Lib, registerEvent, ['NEW_CLASS_INSTANCE', 'ON_TRUE', '[Cup]'], ok(_)),
    lib_iterations(Lib, 1, N, 0, Late),
    Lib = lib(_, _, State, _),
    (   arg(3, State, lost)
    ->  Lost = 1
    ;   Lost = 0
    ),
    arg(2, State, Events),
    length(Events, Received),
    findall(I-C, ( between(1, N, I),
                   format(string(C), "[\"lcup~d\"]", [I]),
                   \+ memberchk(C-_, Events)
                 ), Missing),
    msort(Events, Sorted),
    findall(C, nextto(C-_, C-_, Sorted), Twice),
    append(Missing, Twice, Wrong).

%   lib_iterations(+Lib, +I, +N, +Late0, -Late): Late counts the cups
%   whose event was not read when the reply to the find after their
%   add came.

lib_iterations(_, I, N, Late, Late) :-
    I > N,
    !.
lib_iterations(Lib, I, N, Late0, Late) :-
    format(atom(Add), '[lcup~d rdf:type Cup]', [I]),
    lib_call(Lib, add, [Add], R1),
    lib_call(Lib, find, [x, '[?x rdf:type Table]'], R2),
    (   ( R1 == lost ; R2 == lost )
    ->  Late = Late0
    ;   format(string(C), "[\"lcup~d\"]", [I]),
        Lib = lib(_, _, State, _),
        arg(2, State, Events),
        (   memberchk(C-_, Events)
        ->  Late1 = Late0
        ;   Late1 is Late0 + 1
        ),
        I1 is I + 1,
        lib_iterations(Lib, I1, N, Late1, Late)
    ).

:- begin_tests(events_liboro,
               [ setup(test_server_start([commonsense(true)])),
                 cleanup(test_server_stop)
               ]).

%   1,000 times: add a Cup, then find, on the connection that watches
%   Cup.  Each cup's event must be read before the reply to the find
%   that follows its add, exactly once; the client never finds an
%   event where the reply should already be.

test(add_then_find_1000, [ setup(eo_fresh),
                           true(Result == result(0, 0, 1000, []))
                         ]) :-
    test_server_port(Port),
    setup_call_cleanup(
        lib_connect(Port, listen, Lib),
        lib_cups(Lib, 1000, Result),
        lib_close(Lib)).

%   Events another connection's changes fire are written between this
%   connection's replies, never inside one: each once, in commit order,
%   while it sends requests of its own.  (Such an event may still reach
%   the client while its request is on the way, before the server has
%   read it: the strict client above would take that for a lost
%   connection, as liboro does; see README, Clients.)

test(other_connection, [ setup(eo_fresh),
                         true(Got == Expected)
                       ]) :-
    test_server_port(Port),
    numlist(1, 200, Is),
    maplist([I, C]>>format(string(C), "[\"ocup~d\"]", [I]), Is, Expected),
    setup_call_cleanup(
        ( oro_connect(Port, Listener),
          oro_connect(Port, Other)
        ),
        ( oro_call(Listener, registerEvent, ['NEW_CLASS_INSTANCE', 'ON_TRUE', '[Cup]'],
                   ok(Id)),
          thread_create(forall(member(I, Is),
                               ( format(atom(A), '[ocup~d rdf:type Cup]', [I]),
                                 oro_call(Other, add, [A], ok(_))
                               )),
                        Adder, []),
          findall(R, ( between(1, 300, _),
                       oro_call(Listener, find, [x, '[?x rdf:type Table]'], R)
                     ), Replies),
          thread_join(Adder, Status),
          oro_call(Listener, find, [x, '[?x rdf:type Table]'], _),
          eo_events(Listener, Id, 200, Events),
          (   Status \== true
          ->  Got = adder(Status)
          ;   \+ forall(member(R, Replies), R == ok("[]"))
          ->  Got = replies(Replies)
          ;   Got = Events
          )
        ),
        ( oro_disconnect(Listener),
          oro_disconnect(Other)
        )).

%   eo_events(+Conn, +Id, +N, -Contents): the contents of the next N
%   events of Conn, then any more that come within 0.2 s; all must be
%   those of watcher Id.

eo_events(Conn, Id, N, Contents) :-
    (   N > 0
    ->  oro_next_event(Conn, Event, 5)
    ;   oro_next_event(Conn, Event, 0.2)
    ),
    (   Event = event(Id, Content)
    ->  Contents = [Content|Rest],
        N1 is N - 1,
        eo_events(Conn, Id, N1, Rest)
    ;   Event == timeout,
        N =< 0
    ->  Contents = []
    ;   Contents = [Event]
    ).

:- end_tests(events_liboro).

%   With events_before_reply, a request's events come just before its
%   reply, in the same write: even a client that sends its next request
%   at once after a reply never finds an event left over (with the
%   events after the reply it would read one while it waits, and lose
%   its connection: the real liboro 1.3.1 does, see README, Clients).

:- begin_tests(events_liboro_first,
               [ setup(test_server_start([commonsense(true),
                                          events_before_reply(true)])),
                 cleanup(test_server_stop)
               ]).

test(eager_add_then_find_1000, [ setup(eo_fresh),
                                 true(Result == result(0, 0, 1000, []))
                               ]) :-
    test_server_port(Port),
    setup_call_cleanup(
        lib_connect(Port, eager, Lib),
        lib_cups(Lib, 1000, Result),
        lib_close(Lib)).
test(event_before_its_reply, [ setup(eo_fresh),
                               true(Events == ["[\"first_cup\"]"-1])
                             ]) :-
    test_server_port(Port),
    setup_call_cleanup(
        lib_connect(Port, eager, Lib),
        ( lib_call(Lib, registerEvent, ['NEW_CLASS_INSTANCE', 'ON_TRUE', '[Cup]'], ok(_)),
          lib_call(Lib, add, ['[first_cup rdf:type Cup]'], ok(_)),
          Lib = lib(_, _, State, _),
          arg(2, State, Events)
        ),
        lib_close(Lib)).

:- end_tests(events_liboro_first).

                 /*******************************
                 *          CLEAREVENTS         *
                 *******************************/

:- begin_tests(events_clear_all,
               [ setup(test_server_start([commonsense(true)])),
                 cleanup(test_server_stop)
               ]).

%   pyoro's subscribe() registers with registerEventForAgent myself:
%   clearEvents removes those watchers too (ORO-SPEC §7.1).  Only the
%   sentinel registered afterwards fires.

test(clear_events_for_agent_myself,
     [ setup(eo_fresh),
       true(Events == [S-"[\"cc_mark\"]"])
     ]) :-
    test_server_port(Port),
    setup_call_cleanup(
        oro_connect(Port, Conn),
        ( oro_call(Conn, registerEventForAgent,
                   [myself, 'NEW_INSTANCE', 'ON_TRUE', x, '[?x rdf:type Cup]'], ok(_)),
          oro_call(Conn, registerEvent,
                   ['NEW_CLASS_INSTANCE', 'ON_TRUE', '[Cup]'], ok(_)),
          oro_call(Conn, registerEventForAgent,
                   [default, 'FACT_CHECKING', 'ON_TRUE', '[cc_cup rdf:type Cup]'], ok(_)),
          oro_call(Conn, clearEvents, [], ok("")),
          oro_call(Conn, registerEvent,
                   ['NEW_INSTANCE', 'ON_TRUE', x, '[?x rdf:type Table]'], ok(S)),
          oro_call(Conn, add, ['[cc_cup rdf:type Cup]'], ok(_)),
          oro_call(Conn, add, ['[cc_mark rdf:type Table]'], ok(_)),
          oro_next_event(Conn, E1, 5),
          oro_next_event(Conn, E2, 0.2),
          findall(Id-C, member(event(Id, C), [E1, E2]), Events)
        ),
        oro_disconnect(Conn)).

%   clearEvents leaves oro's own watchers: agent models are still made
%   when an agent is added.

test(clear_events_keeps_agent_models,
     [ setup(eo_fresh),
       true(Reply == ok("[\"paris\"]"))
     ]) :-
    test_call(clearEvents, [], ok("")),
    test_call(add, ['[cc_gerard rdf:type Human]'], ok(_)),
    test_call(addForAgent, [cc_gerard, '[paris loves dancing]'], ok(_)),
    test_call(findForAgent, [cc_gerard, x, '[?x loves dancing]'], Reply).

%   From Prolog: oro_clear_events/1 empties both registries.

test(prolog_clear_events, [ setup(eo_fresh),
                            true(Left == [])
                          ]) :-
    oro_subscriber_create([_, _]>>true, Plain, []),
    oro_subscriber_create([_, _]>>true, Agent, [registry(agent)]),
    call_cleanup(
        ( oro_register_event(myself, new_class_instance, on_true, '', ['Cup'],
                             Plain, _),
          oro_register_event(myself, new_class_instance, on_true, '', ['Table'],
                             Agent, _),
          oro_clear_events(myself),
          oro_watchers(myself, Left)
        ),
        ( oro_subscriber_destroy(Plain),
          oro_subscriber_destroy(Agent)
        )).

:- end_tests(events_clear_all).

:- begin_tests(events_slow_watcher,
               [ setup(test_server_start([commonsense(true)])),
                 cleanup(test_server_stop)
               ]).

%   A reply waits for the watcher thread reply_events_wait seconds at
%   most: here the watcher thread is held by an in-watcher subscriber
%   of the test (on another watcher that the same add fires) until the
%   reply has come; the connection's own event follows, once.

test(reply_not_held_by_a_slow_watcher,
     [ setup(eo_fresh),
       true(Got == reply(ok("")) - events(1))
     ]) :-
    message_queue_create(Gate),
    oro_subscriber_create(hold_watcher(Gate), Holder, [in_watcher(true)]),
    call_cleanup(
        test_with_setting(oro_methods:reply_events_wait, 0.1,
                          slow_watcher_reply(Gate, Holder, Got)),
        ( thread_send_message(Gate, open),
          oro_subscriber_destroy(Holder),
          message_queue_destroy(Gate)
        )).

slow_watcher_reply(Gate, Holder, reply(Reply)-events(N)) :-
    oro_register_event(myself, new_instance, on_true, y, ["?y isOn table1"],
                       Holder, _),
    test_connected(C,
        ( oro_call(C, registerEvent,
                   ["NEW_INSTANCE", "ON_TRUE", "x", "[?x isAt table1]"],
                   ok(_), 10),
          oro_send_raw(C, "add
[cup1 isOn table1]
#end#
"),
          oro_receive(C, Reply0, 10),
          (   Reply0 = event(_, _)                  % the connection's own
          ->  oro_receive(C, Reply, 10),            % event, evaluated first
              Seen = 1
          ;   Reply = Reply0,
              Seen = 0
          ),
          thread_send_message(Gate, open),
          (   Seen == 1
          ->  N = 1
          ;   oro_receive(C, Event, 10),
              (   Event = event(_, _)
              ->  N = 1
              ;   N = 0
              )
          )
        )).

%   hold_watcher(+Gate, +Id, +Content): wait until the test opens Gate
%   (10 s at most).

hold_watcher(Gate, _, _) :-
    ignore(thread_get_message(Gate, open, [timeout(10)])).

:- end_tests(events_slow_watcher).

                 /*******************************
                 *     MINIMUM REPLY LATENCY    *
                 *******************************/

:- begin_tests(reply_latency,
               [ cleanup(test_server_stop)
               ]).

%   With a minimum latency of 100 ms, five replies take 0.5 s at least
%   (a lower bound: a loaded machine only makes them slower).  Events
%   still come with the reply that caused them.

test(delays_replies, [ true(r(Enough, Replies, Event) ==
                            r(true, [ok(""), ok(""), ok("[]"), ok("true")], event))
                     ]) :-
    test_server_start([commonsense(true), min_reply_latency(100)]),
    test_server_port(Port),
    setup_call_cleanup(
        lib_connect(Port, listen, Lib),
        ( get_time(T0),
          lib_call(Lib, registerEvent, ['NEW_CLASS_INSTANCE', 'ON_TRUE', '[Cup]'], ok(_)),
          lib_call(Lib, add, ['[lat_cup rdf:type Cup]'], R1),
          lib_call(Lib, clearEvents, [], R2),
          lib_call(Lib, find, [x, '[?x rdf:type Table]'], R3),
          lib_call(Lib, check, ['[lat_cup rdf:type Cup]'], R4),
          get_time(T1),
          Replies = [R1, R2, R3, R4],
          Lib = lib(_, _, State, _),
          (   arg(2, State, ["[\"lat_cup\"]"-2])
          ->  Event = event
          ;   arg(2, State, Event)
          )
        ),
        lib_close(Lib)),
    (   T1 - T0 >= 0.5
    ->  Enough = true
    ;   Enough = T1 - T0
    ).

%   0, the default, sets no due time for the replies.

test(zero_is_off, [ true(Due == none) ]) :-
    oro_server:reply_due_time(0, Due).
test(default_is_off, [ true(L == 0) ]) :-
    setting(oro_server:min_reply_latency, L).
test(positive_due, [ true(Ahead =:= 0.005) ]) :-
    get_time(T0),
    oro_server:reply_due_time(5, Due),
    get_time(T1),
    Ahead is round((Due - (T0 + T1) / 2) * 1000) / 1000.
test(bad_option, [ error(type_error(nonneg, -1)) ]) :-
    oro_server_start([port(0), commonsense(false), min_reply_latency(-1)], _).

:- end_tests(reply_latency).
