:- module(oro_kbapi_events,
          [ kb_rows/5,                  % +Models, +Patterns, +Vars, -Keys, -Rows
            kb_json_term/2,             % +Term, -JSON
            kb_subscribe/5,             % +Client, +Models, +Patterns, +Shape, -Id
            kb_client_gone/1,           % +Client
            kb_events_reset/0,
            kb_events_sync/0
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(library(oro/oro_store), [oro_model/1]).
:- use_module(library(debug)).
:- use_module(library(md5), [md5_hash/3]).
:- use_module(library(oro)).
:- use_module(library(oro/oro_names)).

/** <module> KB-API queries and subscriptions with bindings

A KB-API subscription (knowledge_core's `subscribe(patterns, one_shot,
models)`) fires with the *new rows* of bindings of every variable of
its patterns, as a list of `{variable: value}` objects; minimalkb's
form (`subscribe(type, trigger, var, patterns, models)`) with the new
values of one variable.  oro_events' watchers follow one variable, so
these subscriptions are evaluated here, the way knowledge_core does it:

  - An rdf_monitor/2 callback on `transaction` only (one call per
    committed change, whoever made it: an ORO client, a KB-API client,
    a planner, forgetting) sends `changed` to this module's thread,
    unless one is waiting already.
  - The thread (alias `oro_kbapi_events`) owns the subscriptions.  On
    `changed` it evaluates each of them on its models (kb_rows/5, in
    oro_store_read/1), keeps the rows it now has and sends the rows
    not seen at the previous evaluation to every client subscribed.
    A one-shot subscription is then removed.
  - Registration is a message to that thread, which evaluates the
    subscription's first rows before it looks at any later change: a
    subscription fires only for what becomes true after it is made.

Identical subscriptions (same patterns, shape, one-shot flag and
models) share an id, `evt_` and the MD5 digest of that description, as
knowledge_core names them; each client subscribed gets the event.  A
client is a message queue owned by the connection (oro_kbapi_methods),
which writes the events; a client whose queue is full has fallen too
far behind and loses its subscriptions.

Cost: every subscription is evaluated again after every change (as in
knowledge_core), one find of its patterns per model.  Changes that come
while an evaluation runs are folded into one: an instance that appears
and goes again in between is not reported.
*/

:- dynamic
    subscription/5,                 % Id, Models, Patterns, Shape, OneShot
    subscribed/2,                   % Id, Client
    previous/2.                     % Id, Rows

		 /*******************************
		 *            QUERIES           *
		 *******************************/

%!  kb_rows(+Models, +Patterns, +Vars, -Keys, -Rows) is det.
%
%   Rows is the ordered set of the solutions of Patterns (statement
%   texts sharing their variables) over Models (resolved model names):
%   the union of the solutions in each.  Each row is a list of values
%   (JSON terms, see kb_json_term/2), one per key of Keys.  Vars are
%   the variable names asked for (`?x` or `x`); `[]` asks for all the
%   named variables of the patterns in the order they appear, or, if
%   there are only anonymous ones (`?__...`, pykb's `*`), for all of
%   them, named `var1`, `var2`... as knowledge_core names them.
%
%   @error domain_error(kb_variable, Var) for a variable the patterns
%          do not use.

kb_rows(Models, Patterns, Vars, Keys, Rows) :-
    must_be(list, Patterns),
    must_be(list, Vars),
    oro_statements(Patterns, Triples, Bindings),
    selected(Vars, Bindings, Keys, Template),
    findall(Row,
            ( member(Model, Models),
              oro_find(Model, Template, Triples, Values),
              member(Value, Values),
              Value =.. [_|Terms],
              maplist(kb_json_term, Terms, Row)
            ),
            Rows0),
    sort(Rows0, Rows).

selected([], Bindings, Keys, Template) :-
    !,
    maplist(binding_name, Bindings, Names),
    exclude(anonymous, Names, Named),
    (   Named == []
    ->  length(Names, N),
        numlist_keys(1, N, Keys),
        maplist(binding_var, Bindings, Vars)
    ;   Keys = Named,
        maplist(binding(Bindings), Named, Vars)
    ),
    Template =.. [row|Vars].
selected(Vars0, Bindings, Keys, Template) :-
    maplist(variable_name, Vars0, Names),
    maplist(binding(Bindings), Names, Vars),
    Keys = Names,
    Template =.. [row|Vars].

binding_name(Name=_, Name).

binding_var(_=Var, Var).

numlist_keys(I, N, []) :-
    I > N,
    !.
numlist_keys(I, N, [Key|Keys]) :-
    atom_concat(var, I, Key),
    I1 is I + 1,
    numlist_keys(I1, N, Keys).

anonymous(Name) :-
    sub_atom(Name, 0, _, _, '__').

variable_name(Text, Name) :-
    must_be(text, Text),
    atom_string(Atom0, Text),
    normalize_space(atom(Atom), Atom0),
    (   sub_atom(Atom, 0, 1, _, ?)
    ->  sub_atom(Atom, 1, _, 0, Name)
    ;   Name = Atom
    ).

binding(Bindings, Name, Var) :-
    (   memberchk(Name=Var, Bindings)
    ->  true
    ;   domain_error(kb_variable, Name)
    ).

%!  kb_json_term(+Term, -JSON) is det.
%
%   The JSON value of an RDF term, as knowledge_core gives it: a
%   resource by its name (`Human`, `rdf:type`, a full IRI otherwise);
%   a number, a boolean or a string literal by its value; another
%   literal by its lexical form.

kb_json_term(Literal, JSON) :-
    Literal = literal(Value),
    !,
    oro_literal_lexical(Literal, Lex),
    (   Value = type(Type, _),
        oro_numeric_datatype(Type, _),
        atom_number(Lex, Number)
    ->  JSON = Number
    ;   Value = type(Type, _),
        rdf_equal(Type, xsd:boolean)
    ->  (   memberchk(Lex, [true, '1'])
        ->  JSON = true
        ;   JSON = false
        )
    ;   atom_string(Lex, JSON)
    ).
kb_json_term(IRI, JSON) :-
    oro_iri_name(IRI, Name),
    atom_string(Name, JSON).

		 /*******************************
		 *         SUBSCRIPTIONS        *
		 *******************************/

%!  kb_subscribe(+Client, +Models, +Patterns, +Shape, -Id) is det.
%
%   Subscribe Client (a message queue, which receives event(Id, Rows)
%   terms) to the new solutions of Patterns in Models.  Shape is
%   rows(OneShot) (each event is a list of rows: dicts of every
%   variable, see kb_rows/5) or values(Var, OneShot) (a list of the new
%   values of Var).  Id is the subscription's id, shared by identical
%   subscriptions.
%
%   @error as kb_rows/5 for bad patterns or an unknown variable.

kb_subscribe(Client, Models, Patterns, Shape, Id) :-
    must_be(list, Models),
    must_be(list, Patterns),
    shape_vars(Shape, Vars),
    kb_rows(Models, Patterns, Vars, _, _),      % errors here, not in the thread
    term_to_atom(kb(Patterns, Shape, Models), Description),
    md5_hash(Description, Hash, []),
    atom_concat(evt_, Hash, Id),
    ensure_thread,
    call_thread(subscribe(Id, Client, Models, Patterns, Shape)).

shape_vars(rows(OneShot), []) :-
    must_be(boolean, OneShot).
shape_vars(values(Var, OneShot), [Var]) :-
    must_be(boolean, OneShot).

%!  kb_client_gone(+Client) is det.
%
%   Client (a connection that closed) loses its subscriptions; those
%   left without a client are removed.

kb_client_gone(Client) :-
    (   thread_running
    ->  call_thread(gone(Client))
    ;   true
    ).

%!  kb_events_reset is det.
%
%   Remove every subscription (KB-API `clear`, as knowledge_core does).

kb_events_reset :-
    (   thread_running
    ->  call_thread(reset)
    ;   true
    ).

%!  kb_events_sync is det.
%
%   Wait until every change committed before the call has been
%   evaluated and its events sent to the clients' queues.

kb_events_sync :-
    (   thread_running
    ->  call_thread(sync)
    ;   true
    ).

		 /*******************************
		 *            THREAD            *
		 *******************************/

thread_running :-
    catch(thread_property(oro_kbapi_events, status(running)), _, fail).

ensure_thread :-
    with_mutex(oro_kbapi_events,
               (   thread_running
               ->  true
               ;   (   catch(message_queue_property(oro_kbapi_events_queue,
                                                    size(_)), _, fail)
                   ->  true
                   ;   message_queue_create(_, [alias(oro_kbapi_events_queue)])
                   ),
                   catch(thread_join(oro_kbapi_events, _), _, true),
                   thread_create(events_loop, _, [alias(oro_kbapi_events)]),
                   rdf_monitor(oro_kbapi_events:monitor, [-all, +transaction])
               )).

call_thread(Request) :-
    thread_self(Me),
    gensym(oro_kbapi_reply_, Tag),
    thread_send_message(oro_kbapi_events_queue, call(Request, Me, Tag)),
    thread_get_message(reply(Tag, Result)),
    (   Result = error(E)
    ->  throw(E)
    ;   true
    ).

%   monitor(+Event): a committed change, other than oro_events' own
%   snapshots, asks for one evaluation if there are subscriptions.
%   Tiny and total: it never blocks (the queue is unbounded), sends
%   nothing while a `changed` is waiting, and changes no clause (a
%   flag says a `changed` waits), so that writes leave no work to the
%   clause garbage collector (see oro_store).

monitor(transaction(end(0), Id)) :-
    Id \== oro(events),
    subscription(_, _, _, _, _),
    !,
    flag(oro_kbapi_change_waiting, Waiting, 1),
    (   Waiting == 1
    ->  true
    ;   catch(thread_send_message(oro_kbapi_events_queue, changed), _, true)
    ).
monitor(_).

events_loop :-
    thread_get_message(oro_kbapi_events_queue, Message),
    catch(handle(Message), E, print_message(error, E)),
    events_loop.

handle(changed) :-
    flag(oro_kbapi_change_waiting, _, 0),
    forall(subscription(Id, _, _, _, _),
           catch(evaluate(Id), E, print_message(error, E))).
handle(call(Request, Thread, Tag)) :-
    (   catch(request(Request), E, true)
    ->  (   var(E)
        ->  Result = done
        ;   Result = error(E)
        )
    ;   Result = error(error(oro_kbapi(failed(Request)), _))
    ),
    thread_send_message(Thread, reply(Tag, Result)).

request(subscribe(Id, Client, Models, Patterns, Shape)) :-
    (   subscription(Id, _, _, _, _)
    ->  true
    ;   current_rows(Models, Patterns, Shape, Rows),
        shape_one_shot(Shape, OneShot),
        assertz(subscription(Id, Models, Patterns, Shape, OneShot)),
        assertz(previous(Id, Rows))
    ),
    (   subscribed(Id, Client)
    ->  true
    ;   assertz(subscribed(Id, Client))
    ),
    debug(oro(kbapi), 'Subscription ~w: ~q', [Id, Patterns]).
request(gone(Client)) :-
    retractall(subscribed(_, Client)),
    forall(( subscription(Id, _, _, _, _),
             \+ subscribed(Id, _)
           ),
           remove(Id)).
request(reset) :-
    retractall(subscription(_, _, _, _, _)),
    retractall(subscribed(_, _)),
    retractall(previous(_, _)).
request(sync) :-
    (   thread_peek_message(oro_kbapi_events_queue, changed)
    ->  thread_get_message(oro_kbapi_events_queue, changed),
        handle(changed)
    ;   true
    ).

shape_one_shot(rows(OneShot), OneShot).
shape_one_shot(values(_, OneShot), OneShot).

remove(Id) :-
    retractall(subscription(Id, _, _, _, _)),
    retractall(subscribed(Id, _)),
    retractall(previous(Id, _)).

%   current_rows(+Models, +Patterns, +Shape, -Rows): the solutions now,
%   as the events report them (dicts, or values), as an ordered set.
%   A model removed meanwhile (reset) is left out.

current_rows(Models0, Patterns, Shape, Rows) :-
    include(oro_model, Models0, Models),
    shape_vars(Shape, Vars),
    oro_store_read(kb_rows(Models, Patterns, Vars, Keys, Rows0)),
    (   Shape = values(_, _)
    ->  findall(V, member([V], Rows0), Rows1)
    ;   findall(Dict,
                ( member(Row, Rows0),
                  pairs_keys_values(Pairs, Keys, Row),
                  dict_pairs(Dict, row, Pairs)      % a tag: rows compare
                ),
                Rows1)
    ),
    sort(Rows1, Rows).

evaluate(Id) :-
    subscription(Id, Models, Patterns, Shape, OneShot),
    previous(Id, Old),
    current_rows(Models, Patterns, Shape, Rows),
    retractall(previous(Id, _)),
    assertz(previous(Id, Rows)),
    ord_subtract(Rows, Old, New),
    (   New == []
    ->  true
    ;   debug(oro(kbapi), 'Event ~w: ~q', [Id, New]),
        forall(subscribed(Id, Client), notify(Id, Client, New)),
        (   OneShot == true
        ->  remove(Id)
        ;   true
        )
    ).

%   notify(+Id, +Client, +Rows): a client whose queue is full loses its
%   subscriptions.

notify(Id, Client, Rows) :-
    (   catch(thread_send_message(Client, event(Id, Rows), [timeout(0)]),
              _, fail)
    ->  true
    ;   print_message(warning,
                      format("oro: a KB-API client is too far behind its \c
                              events: its subscriptions are removed", [])),
        request(gone(Client))
    ).
